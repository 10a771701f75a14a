// A closed-loop study (`mode: outcomes` in a study file; docs/studies.md
// "Outcome mode"): sensor sets crossed with strategies, each run as one
// episode in each world of each world family with each seed, scored by how
// the episode ended. Read and validated like a scenario: every problem listed
// at once, before any run.
//
//   proxsim_study: 1
//   mode: outcomes
//   base: ../scenarios/outcomes_base.yaml   # robot, gait, timing; its scene, sensors, path and strategy replaced
//   sets:                                   # sensor sets, each a scenario's `sensors:` list
//     - {name: two_tof, sensors: [{name: l, type: vl53l0x, link: left_tibia, pose: {...}}, ...]}
//   combine: {from: study-out/ranking.csv, size: 2, top: 4}   # and/or every set of `size` of the top mountings
//   strategies: [{name: stop}, {name: circumvent, margin_m: 0.2}, none]
//   tune: {stop.min_height_m: [0.03, 0.05, 0.08]}   # each set's values chosen on the training seeds
//   worlds:                                 # one map or a list of them
//     - {generate: {kind: room, difficulty: [0.3, 0.6], size_m: [5, 5]},
//        seeds: {train: {from: 1, to: 20}, test: {from: 21, to: 70}}}
//     - {name: corridor, scenario: my_corridor.yaml, seeds: [1, 2, 3]}   # test seeds only (nothing tuned)
//   target_success: 0.95
//   prices: {vl53l0x: {price_usd: 9.5}, my_sensor: {price_usd: 120, mass_g: 30}}   # by sensor name, then part or type
//   replay_files: 1000                      # failed runs whose replay world is written
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace proxsim {

/// One candidate set of sensors: what a robot would be bought with.
struct SensorSet {
  std::string name;
  std::string sensors_yaml;  ///< the set as a scenario's `sensors:` list (YAML, flow style)
  std::vector<std::string> sensor_names;
  double price_usd = 0;      ///< the sum over its sensors; NaN when one has no price
  double mass_g = 0;         ///< the sum; NaN when one has no mass
  std::vector<std::string> unpriced;  ///< its sensors without a price (why price_usd is NaN)
  /// "" for a candidate set; "blind" or "oracle" for a baseline the study adds
  /// (outcome_baselines.h): rows of the answer, never a set to buy.
  std::string baseline;
};

/// What a run's failures cost, for the expected cost per run (CostNav's
/// spirit: a navigation stack ranked by dollars per run): the set's price
/// amortised over runs_per_unit runs, plus each collision's and each fall's.
struct RunCosts {
  double runs_per_unit = 1000;  ///< runs one unit of hardware lasts, > 0
  double collision_usd = 50;    ///< a collision: a bumped object, a scratched shin
  double fall_usd = 500;        ///< a fall: a humanoid's repair and downtime
};

/// One strategy the sets are run with: a strategy of the study file, or one
/// variant of it when `tune:` gives candidate values for its parameters.
struct StrategyChoice {
  /// its name, with its parameters where a name repeats (stop[min_height_m=0.05]), and
  /// the tuned values of a variant after them: `group`[`tuned`]
  std::string label;
  std::string yaml;           ///< the scenario's `robot.strategy` map; empty: none (the walk goes on)
  /// the strategy of the study file this is a variant of (its label without
  /// the tuned values): a set is ranked once per group, with its best variant
  std::string group;
  std::string tuned;          ///< the tuned values, "min_height_m=0.05,stop_distance_m=0.4"; "" when nothing is tuned
};

/// One kind of world: a generated kind at one difficulty, or a scenario.
struct WorldFamily {
  std::string name;           ///< room_d0.3, course_d0.6, or the scenario variant's name
  std::string kind;           ///< room, course, or scenario
  double difficulty = 0;      ///< NaN for a scenario
  std::string document_yaml;  ///< the scenario, without sensors or strategy; a generated one with `scene.generate` (its seed set per job)
  std::string source;         ///< the file relative paths are resolved from (the base, or the variant's file)
  bool generated = false;
};

struct OutcomeStudyConfig {
  std::string source;
  std::vector<SensorSet> sets;
  std::vector<StrategyChoice> strategies;
  std::vector<WorldFamily> families;
  /// A job: one family with one seed (the world's and the noise's); every run of
  /// every set with every strategy in it.
  struct Job {
    std::size_t family = 0;
    std::uint64_t seed = 0;
    /// a training seed: its runs choose each set's strategy values (`tune:`),
    /// and are not counted in the answer; the test seeds' runs are
    bool train = false;
  };
  std::vector<Job> jobs;
  double target_success = 0.95;
  std::size_t replay_files = 1000;
  RunCosts costs;
  /// The baselines run beside the sets (their rows last in `sets`): blind and oracle by default.
  std::vector<std::string> baselines{"blind", "oracle"};
  std::size_t runs_per_job() const { return sets.size() * strategies.size(); }
  /// The strategy groups in the order given (StrategyChoice::group), each with its variants' indices.
  std::vector<std::pair<std::string, std::vector<std::size_t>>> strategy_groups() const;
};

/// Bounds on an outcome study's size (each run is an episode of its own).
inline constexpr std::size_t kMaxOutcomeSets = 10'000;
inline constexpr std::size_t kMaxOutcomeRuns = 1'000'000;

/// Whether a study file says `mode: outcomes` (anything else is read as a
/// detection study, which reports a bad mode).
bool IsOutcomeStudyFile(const std::string& path);

/// Reads and validates an outcome study; throws InputError listing every problem.
OutcomeStudyConfig LoadOutcomeStudyFile(const std::string& path, bool allow_large = false);

/// The scenario text of one run: the job's world, the set's sensors, the
/// strategy, `seed` the job's seed. What the run reads, and what its replay
/// file holds. (RunTextFromWorld with `reference` makes the job's reference
/// walk instead.) The reference: no sensors, no strategy, legs that feel the
/// true ground and refuse an unsafe step (`gait.footholds: truth`,
/// `gait.unsafe_steps: refuse`), ended by its first collision — the episode
/// that tells whether the path given can be walked at all, and where not.
std::string RunScenarioText(const OutcomeStudyConfig& study, std::size_t job, std::size_t set, std::size_t strategy);

/// The job's world without sensors or strategy (generated, for a generated family).
std::string WorldText(const OutcomeStudyConfig& study, std::size_t job);
/// A run's text from its job's WorldText (what RunScenarioText does, without regenerating the world).
std::string RunTextFromWorld(const std::string& world_text, const SensorSet* set, const StrategyChoice* strategy,
                             bool reference);

/// The same two as documents, for running: WorldText is WorldNode written
/// out, RunTextFromWorld is RunNodeFromWorld written out (the world node is
/// copied, never changed). An episode run from the node reads the very
/// values its replay text holds, without writing and parsing the text.
YAML::Node WorldNode(const OutcomeStudyConfig& study, std::size_t job);
YAML::Node RunNodeFromWorld(const YAML::Node& world, const SensorSet* set, const StrategyChoice* strategy,
                            bool reference);
/// The same for the world's last run: the world node itself becomes the
/// run's (no copy: ~3 M instructions for a generated room).
YAML::Node RunNodeFromWorld(YAML::Node&& world, const SensorSet* set, const StrategyChoice* strategy, bool reference);

}  // namespace proxsim
