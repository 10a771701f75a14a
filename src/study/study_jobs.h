// The machinery every study mode shares (docs/studies.md "Scale"): jobs
// handed out one at a time to worker threads and, under mpirun, to the other
// ranks; each finished job appended to OUT/journal.jsonl and flushed to disk
// before the next is handed out (a study killed at any moment, SIGKILL
// included, and restarted with resume loses and redoes no job); a progress
// line; the results read back from the journal in job order, so the files
// written from them do not depend on who ran which job.
//
// A mode brings what differs: how one job is run (a worker per thread, built
// before any job runs) and what its journal line must look like (checked on
// every line read back and every MPI message received).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/output_folder.h"
#include "study/study_mpi.h"
#include "study/study_shard.h"

namespace proxsim {

struct StudyOptions {
  std::string out_dir = "study-out";
  int threads = 0;      ///< worker threads in this process; 0: every core (1 per rank under MPI)
  bool resume = false;  ///< keep the journal's finished jobs
  bool progress = true; ///< a progress line on stderr (rank 0)
  bool force = false;   ///< write into a non-empty folder that holds no previous study (--force)
  /// Receives the claimed, locked output folder (rank 0), to hold while the
  /// answers and figures are written; the lock ends with the last holder.
  std::shared_ptr<OutputFolder>* folder = nullptr;
  /// Run only this slice of the jobs (--shard), into a folder of the slice's
  /// own: its journal holds the slice's jobs only, OUT/slice.json says which.
  std::optional<StudySlice> slice = std::nullopt;
};

/// One study mode's jobs, for RunJobs.
struct JobSet {
  std::size_t jobs = 0;       ///< job indices 0 .. jobs-1
  std::size_t runs_per_job = 1;  ///< for the progress line's run count
  std::string fingerprint;    ///< what makes a journal this study's (StudyFingerprint)
  std::string digest;         ///< the study's content (StudyDigest): what makes slices one study's
  std::string mode;           ///< "detection" or "outcomes", for a slice's record
  std::string study_file;     ///< the study file as given, for a slice's record (merge reads it again)
  /// Checks a journal line or MPI message {"job": J, "metrics": ...} against
  /// the study's shape and returns J; throws InputError saying what does not fit.
  std::function<std::size_t(const nlohmann::json& line)> check;
  /// One per worker thread (WorkerThreads of them), built before any job
  /// runs: a job's "metrics" JSON.
  std::vector<std::function<nlohmann::json(std::size_t job)>> workers;
  std::string header;         ///< the progress's first line: what the study runs
};

/// How many worker threads this process runs: `requested` if > 0, else one
/// per core (one per rank under MPI).
int WorkerThreads(int requested, const StudyMpi& mpi);

/// A journal's fingerprint from the text that identifies a study: FNV-1a 64
/// (the same in every build, unlike std::hash), after a readable `shape`.
std::string StudyFingerprint(const std::string& shape, const std::string& identity);

/// A journal's first line: the study's fingerprint, and the slice for a slice's journal.
nlohmann::json JournalHeader(const std::string& fingerprint, const std::optional<StudySlice>& slice);

/// Reads a journal's finished jobs, every line checked with `check` (a line
/// cut short by a kill is dropped) and, for a slice, each job checked to be
/// the slice's; a missing file has none. Throws InputError naming the file
/// (and line) when its header is not `header` or a line does not fit.
std::map<std::size_t, std::string> ReadJournal(const std::string& path, const nlohmann::json& header,
                                               const std::function<std::size_t(const nlohmann::json&)>& check,
                                               const std::optional<StudySlice>& slice);

/// Runs every job not already in the journal (options.resume) on the workers
/// and the other ranks; returns every job's journal line (one per job) on
/// rank 0 with `is_writer` true, nothing on the other ranks, which run jobs
/// for rank 0 until none is left. With options.slice, only that slice's jobs
/// (and lines), and OUT/slice.json written.
std::map<std::size_t, nlohmann::json> RunJobs(const JobSet& set, const StudyOptions& options, StudyMpi& mpi,
                                              bool* is_writer);

}  // namespace proxsim
