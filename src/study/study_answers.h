// A study's answers from its runs' metrics: one row per run (results.csv),
// single mountings ranked (ranking.csv), the best set of k sensors chosen
// greedily for hazard coverage and the Pareto front of sensor count against
// detection rate and lead distance (selection.json).
//
// The selection's objective and why greedy is sound for it: study_selection.h.
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

/// Writes results.csv, ranking.csv and selection.json into out_dir; returns selection.json's content.
nlohmann::json WriteStudyAnswers(const StudyConfig& study, const StudyResults& results, const std::string& out_dir);

}  // namespace proxsim
