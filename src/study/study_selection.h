// The best set of k sensors, chosen greedily, and the objective it maximises.
//
// An item is one hazard in one scene variant with one seed (where the variant
// has that hazard). A candidate that detected an item earns it a weight
//   w = 1 + max(lead_m, 0) / lead_scale_m,
// and a set of sensors is worth the sum over items of its best weight there:
//   value(S) = Σ_items max_{s ∈ S} w(s, item)   (0 for an item no s detected).
// lead_scale_m exceeds the items' count times the longest lead, so all the
// lead terms together weigh less than one item: a set that covers more
// items is always worth more, and among sets that cover as many, the one that
// sees each hazard from farther ahead. This is a weighted coverage (facility
// location) function with non-negative weights: monotone and submodular (a
// sensor adds no more to a larger set than to a smaller one), so the greedy
// choice — at each step the candidate that adds the most value — is within a
// factor 1 − 1/e ≈ 0.63 of the best set of the same size (Nemhauser, Wolsey
// and Fisher, 1978), in k passes over the candidates instead of C(n, k) sets.
#pragma once

#include <cstddef>
#include <vector>

#include "study/study_config.h"
#include "study/study_runner.h"

namespace proxsim {

/// The items each candidate detected, as indices into one list of items.
struct Coverage {
  std::size_t items = 0;                          ///< applicable (variant, seed, hazard) items
  std::vector<std::vector<std::size_t>> covers;   ///< per candidate, sorted item indices it detected
  std::vector<std::vector<double>> lead_m;        ///< per candidate, the lead for each covered item (same order)
  double lead_scale_m = 1.0;                      ///< see the top of this file
};
Coverage CoverageOf(const StudyConfig& study, const StudyResults& results);

/// value(S) of the top of this file.
double SelectionValue(const Coverage& coverage, const std::vector<std::size_t>& set);

/// Below this, a sensor's improvement of the leads (summed over items) is noise, not a reason to add it.
constexpr double kNegligibleLeadGain_m = 1e-3;

/// The greedy order of up to k candidates among the eligible ones; stops
/// early when no candidate covers a new item or lengthens the leads by more
/// than kNegligibleLeadGain_m. `rank` breaks ties (lower first).
std::vector<std::size_t> GreedySelection(const Coverage& coverage, std::size_t k, const std::vector<std::size_t>& rank,
                                         const std::vector<bool>& eligible);

}  // namespace proxsim
