// A study's answers from its runs' metrics: one row per run (results.csv),
// single mountings ranked (ranking.csv), the best set of k sensors chosen
// greedily for hazard coverage and the Pareto front of sensor count against
// detection rate and lead distance (selection.json).
//
// Coverage: an item is one hazard in one scene variant with one seed (where
// the variant has that hazard); a set of sensors covers the items any of them
// detected. The selection maximises the number of items covered. Coverage is
// monotone and submodular (a sensor adds no more to a larger set than to a
// smaller one), so the greedy choice — at each step the sensor that covers
// the most items not yet covered — is within a factor 1 − 1/e ≈ 0.63 of the
// best set of the same size (Nemhauser, Wolsey and Fisher, 1978), and it
// needs k passes over the candidates instead of C(n, k) sets. Ties go to the
// larger sum of lead distances over the newly covered items, then to rank.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/study_config.h"
#include "study/study_runner.h"

namespace proxsim {

/// Mean and half-width of the 95 % interval (Student's t over the values;
/// half-width 0 for one value); NaN mean for no value.
struct MeanCi {
  double mean = 0, ci95 = 0;
};
MeanCi MeanWithCi95(const std::vector<double>& values);

/// The items each candidate covers, as indices into one list of items.
struct Coverage {
  std::size_t items = 0;                       ///< applicable (variant, hazard, seed) items
  std::vector<std::vector<std::size_t>> covers;  ///< per candidate, sorted item indices it detected
  std::vector<std::vector<double>> lead_m;       ///< per candidate, the lead for each covered item (same order)
};
Coverage CoverageOf(const StudyConfig& study, const StudyResults& results);

/// The greedy order of up to k candidates (see the top of this file); `rank`
/// breaks the remaining ties (lower first).
std::vector<std::size_t> GreedySelection(const Coverage& coverage, std::size_t k, const std::vector<std::size_t>& rank);

/// Writes results.csv, ranking.csv and selection.json into out_dir; returns selection.json's content.
nlohmann::json WriteStudyAnswers(const StudyConfig& study, const StudyResults& results, const std::string& out_dir);

}  // namespace proxsim
