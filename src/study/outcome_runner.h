// Runs an outcome study's episodes on every core, or over MPI ranks,
// resumably — the machinery of study_jobs.h. A job is one world (a family
// with one seed): the worker generates it once, walks it once with no
// sensors and legs that refuse an unsafe step (the reference: can the path be
// walked at all?), then runs every set with every strategy in it, each an
// episode of its own (each set steers its own walk). A run is the scenario
// text RunTextFromWorld makes — the same text a failed run's replay file holds.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "referee/referee.h"
#include "study/outcome_config.h"
#include "study/study_jobs.h"

namespace proxsim {

/// What one episode measured.
struct OutcomeRun {
  OutcomeKind outcome = OutcomeKind::kTimeUp;  ///< how the episode ended (its name: OutcomeName)
  double outcome_t_s = 0;
  double walked_m = 0;          ///< the path the robot walked
  double straight_m = 0;        ///< start to goal in a straight line; NaN without a path
  double min_clearance_m = 0;   ///< the robot's least distance to the scene (0 on contact); NaN if never measured
};

/// One job's episodes: runs[set · strategies + strategy].
struct OutcomeJob {
  bool way_through = true;      ///< the reference walk got to the goal along the path given
  double hazard_m = 0;          ///< without a way through: how far the reference walked before it met the hazard
  /// without a way through: a stop counts as "before the hazard" within this
  /// path length of hazard_m (kStopBeforeHazard_m or kStopBeforeObstacle_m)
  double stop_window_m = 2.0;
  std::vector<OutcomeRun> runs;
};

/// Where the reference walk stood refused (a step its legs cannot take), a
/// stop counts as "before the hazard" within this path length of it: a robot
/// that stops at its start does not succeed for it. About three of the
/// paper's strides: the stop rule on the stairs-hole example stops 1.4 m
/// short, on a drop its lasers saw 0.16 m ahead of the toe.
inline constexpr double kStopBeforeHazard_m = 2.0;
/// Where the reference walk collided (something in the way of the straight
/// path, a generated room's blockers), within this: the stop rule's 0.5 m
/// look-ahead from the toe, the toe up to 0.3 m ahead of the pelvis, and
/// half a stride to the next double support.
inline constexpr double kStopBeforeObstacle_m = 1.2;

using OutcomeResults = std::vector<OutcomeJob>;  ///< per job

/// Whether a run counts as a success: it reached its goal, or, in a world
/// with no way through, it stopped (its strategy, or its legs refusing)
/// within kStopBeforeHazard_m of the hazard.
bool IsSuccess(const OutcomeRun& run, const OutcomeJob& job);

/// A job as its journal line's "metrics", and back (checked against the
/// study's shape: a malformed or foreign line is an InputError).
nlohmann::json OutcomeJobJson(const OutcomeJob& job);
OutcomeJob ParseOutcomeJob(const nlohmann::json& metrics, std::size_t runs_per_job, const std::string& where);

/// One episode of a run's scenario text, on a world of its own (the microbenchmark's episode).
OutcomeRun RunEpisode(const std::string& scenario_text, const std::string& source);

/// The study's jobs as RunJobs and a merge of slices take them: count,
/// fingerprint, digest, the journal line's check (no workers).
JobSet OutcomeJobSet(const OutcomeStudyConfig& study);

/// Every job's episodes from its journal lines (one per job, each checked):
/// what the answers are written from, whoever ran the jobs.
OutcomeResults OutcomeResultsFromJournal(const OutcomeStudyConfig& study,
                                         const std::map<std::size_t, nlohmann::json>& lines);

/// Runs every job not in the journal; returns the results on rank 0 (and
/// `is_writer` true there), nothing on the other ranks nor for a slice
/// (options.slice: its journal is merged later). Every family's first
/// world is built with every set before any run, so a bad link, a bad
/// generate key or a set that does not fit the robot fails first (InputError).
OutcomeResults RunOutcomeStudy(const OutcomeStudyConfig& study, const StudyOptions& options, bool* is_writer);

}  // namespace proxsim
