#include "study/study_selection.h"

#include <algorithm>

namespace proxsim {

namespace {

double Weight(const Coverage& coverage, std::size_t candidate, std::size_t j) {
  return 1.0 + std::max(coverage.lead_m[candidate][j], 0.0) / coverage.lead_scale_m;
}

}  // namespace

Coverage CoverageOf(const StudyConfig& study, const StudyResults& results) {
  Coverage coverage;
  coverage.covers.resize(study.candidates.size());
  coverage.lead_m.resize(study.candidates.size());
  double longest_lead_m = 0;
  for (std::size_t v = 0; v < study.variants.size(); ++v) {
    for (std::size_t s = 0; s < study.seeds.size(); ++s) {
      for (std::size_t h = 0; h < study.hazards.size(); ++h) {
        if (results[v][s].empty() || !results[v][s][0].hazards[h].applies) continue;
        const std::size_t item = coverage.items++;
        for (std::size_t c = 0; c < study.candidates.size(); ++c) {
          const HazardResult& r = results[v][s][c].hazards[h];
          if (!r.detected) continue;
          coverage.covers[c].push_back(item);
          coverage.lead_m[c].push_back(r.lead_m);
          longest_lead_m = std::max(longest_lead_m, r.lead_m);
        }
      }
    }
  }
  coverage.lead_scale_m = (static_cast<double>(coverage.items) + 1.0) * std::max(longest_lead_m, 1.0);
  return coverage;
}

double SelectionValue(const Coverage& coverage, const std::vector<std::size_t>& set) {
  std::vector<double> best(coverage.items, 0.0);
  for (std::size_t c : set) {
    for (std::size_t j = 0; j < coverage.covers[c].size(); ++j) {
      best[coverage.covers[c][j]] = std::max(best[coverage.covers[c][j]], Weight(coverage, c, j));
    }
  }
  double value = 0;
  for (double w : best) value += w;
  return value;
}

std::vector<std::size_t> GreedySelection(const Coverage& coverage, std::size_t k, const std::vector<std::size_t>& rank,
                                         const std::vector<bool>& eligible) {
  const std::size_t n = coverage.covers.size();
  std::vector<double> best(coverage.items, 0.0);  // the chosen set's best weight per item
  std::vector<bool> chosen(n, false);
  std::vector<std::size_t> order;
  while (order.size() < k) {
    std::size_t pick = n;
    double pick_gain = 0;
    for (std::size_t c = 0; c < n; ++c) {
      if (chosen[c] || !eligible[c]) continue;
      double gain = 0;
      for (std::size_t j = 0; j < coverage.covers[c].size(); ++j) {
        gain += std::max(Weight(coverage, c, j) - best[coverage.covers[c][j]], 0.0);
      }
      if (gain > pick_gain || (gain == pick_gain && pick < n && rank[c] < rank[pick])) {
        pick = c;
        pick_gain = gain;
      }
    }
    if (pick == n || pick_gain * coverage.lead_scale_m <= kNegligibleLeadGain_m) break;  // nothing left adds anything
    chosen[pick] = true;
    order.push_back(pick);
    for (std::size_t j = 0; j < coverage.covers[pick].size(); ++j) {
      best[coverage.covers[pick][j]] = std::max(best[coverage.covers[pick][j]], Weight(coverage, pick, j));
    }
  }
  return order;
}

}  // namespace proxsim
