// The study journal's lines (OUT/journal.jsonl): one finished job each,
// `{"job": J, "metrics": [per candidate: {"h": [[applies, detected,
// first_t_s, lead_m] per hazard], "n", "fa", "self", "graze", "floor"}]}`.
//
// A journal is read back by --resume, and it may have been cut by a kill,
// written by another study or edited by hand: every line is checked against
// the study's shape (job index in range, one entry per candidate, one per
// hazard, every field of its type) before anything is taken from it, so a
// foreign or malformed line is an input error, never an out-of-bounds read.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/run_metrics.h"

namespace proxsim {

/// What every line of one study's journal must look like.
struct JournalShape {
  std::size_t jobs = 0;        ///< variants x seeds
  std::size_t candidates = 0;  ///< entries in "metrics"
  std::size_t hazards = 0;     ///< entries in each candidate's "h"
};

struct JournalEntry {
  std::size_t job = 0;
  std::vector<RunMetrics> metrics;  ///< one per candidate
};

/// A job's metrics as the journal's JSON ("metrics").
nlohmann::json JournalMetricsJson(const std::vector<RunMetrics>& runs);

/// Parses and checks one journal line (or one MPI message, which has the same
/// form); throws InputError saying what in the line does not fit the shape.
JournalEntry ParseJournalLine(const nlohmann::json& line, const JournalShape& shape);

}  // namespace proxsim
