// Runs a study's runs on every core, or over MPI ranks, resumably.
//
// A job is one scene variant with one seed: one simulation carries every
// candidate mounting at once (the candidates do not steer the walk: the
// variant has no strategy), so a job gives one run — one row — per candidate.
// Each worker builds its variants' worlds once and resets them between jobs.
// Jobs are handed out one at a time (threads take them from a shared counter;
// under mpirun, rank 0 hands them to the other ranks on request and works on
// them itself too). Every finished job is appended to OUT/journal.jsonl and
// flushed to disk before the next is handed out, so a study killed at any
// moment (SIGKILL included) and restarted with resume loses and redoes no job.
// The results do not depend on the number of workers or on the order jobs
// finished in: they are written sorted by job.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/run_metrics.h"
#include "study/study_config.h"
#include "study/study_jobs.h"

namespace proxsim {

/// The metrics of every job: [variant][seed][candidate].
using StudyResults = std::vector<std::vector<std::vector<RunMetrics>>>;

/// The study's jobs as RunJobs and a merge of slices take them: count,
/// fingerprint, digest, the journal line's check (no workers).
JobSet StudyJobSet(const StudyConfig& study);

/// Every job's metrics from its journal lines (one per job, each checked):
/// what the answers are written from, whoever ran the jobs.
StudyResults StudyResultsFromJournal(const StudyConfig& study, const std::map<std::size_t, nlohmann::json>& lines);

/// Runs every job not in the journal; returns the results on rank 0 (and
/// `is_writer` true there), empty results on the other ranks and for a slice
/// (options.slice: its journal is merged later). Builds every variant's world
/// before the first run, so a bad link fails first (InputError).
StudyResults RunStudy(const StudyConfig& study, const StudyOptions& options, bool* is_writer);

}  // namespace proxsim
