// Edit distance with one rolling row (O(|a|·|b|) time, O(|b|) memory): keys
// are a few characters long, so nothing cleverer is needed.
#include "core/nearest_key.h"

#include <algorithm>
#include <numeric>

namespace proxsim {

std::size_t EditDistance(std::string_view a, std::string_view b) {
  // row[j] holds the distance between the first i characters of a and the first j of b
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];  // distance(a[0, i-1), b[0, j-1))
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

std::optional<std::string> NearestKey(std::string_view word, const std::vector<std::string>& candidates) {
  // a key written without its suffix ("radius" for "radius_m")
  if (word.size() >= 2) {
    for (const auto& candidate : candidates) {
      if (candidate.starts_with(word)) return candidate;
    }
  }
  // else the nearest, if it is close enough to be a typo
  const std::size_t max_edits = std::max<std::size_t>(2, word.size() / 2);
  std::optional<std::string> best;
  std::size_t best_distance = max_edits + 1;
  for (const auto& candidate : candidates) {
    const std::size_t distance = EditDistance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

}  // namespace proxsim
