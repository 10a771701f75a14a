// An outcome study's answers from its episodes (docs/studies.md "Outcome
// mode"): one row per run (results.csv, training runs and every variant
// too); each set with each strategy, at the variant chosen for it on the
// training worlds (`tune:`), measured on the test worlds and ranked by
// perception score (its success between the blind and oracle baselines'),
// then success rate with its 95 % Wilson interval, with collision, fall and
// stop rates, median time to goal and the expected cost per run
// (ranking.csv); every two sets compared on the same worlds and seeds by
// McNemar's exact test (pairs.csv); the cheapest set reaching the target
// success rate, the lowest expected cost and the Pareto front of price
// against success (selection.json); and every failed run of the answer with
// the command that replays it and its world file (failures.csv, failures/*.yaml).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "study/outcome_config.h"
#include "study/outcome_runner.h"

namespace proxsim {

/// Pairs are compared among at most this many sets per strategy (the best
/// ranked): 100 sets make 4950 pairs.
inline constexpr std::size_t kMaxPairedSets = 100;

/// Writes the files into out_dir; returns selection.json's content. The
/// replay commands in failures.csv run from inside out_dir (its paths are
/// relative to it, so the files do not depend on where the study was written).
nlohmann::json WriteOutcomeAnswers(const OutcomeStudyConfig& study, const OutcomeResults& results,
                                   const std::string& out_dir);

}  // namespace proxsim
