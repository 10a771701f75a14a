// "Did you mean …?" for misspelt keys and names: the nearest candidate by edit
// distance, offered only when it is close enough to be a plausible typo.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace proxsim {

/// Levenshtein distance: the fewest single-character insertions, deletions
/// and substitutions that turn `a` into `b`.
std::size_t EditDistance(std::string_view a, std::string_view b);

/// The candidate `word` most plausibly misspells: first one that `word` begins
/// (a unit suffix left out: "rpy" for "rpy_deg"), else the nearest by edit
/// distance (the first on a tie) if within max(2, |word| / 2) edits; nullopt
/// when nothing is that close.
std::optional<std::string> NearestKey(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace proxsim
