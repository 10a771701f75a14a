// A sensor-placement study (`proxsim study STUDY.yaml`): a base scenario, the
// candidate mountings (axes to combine, or an explicit list), scene variants,
// seeds, the hazards that matter and how many sensors to select. Read and
// validated like a scenario: every problem listed at once, before any run.
//
//   proxsim_study: 1
//   base: ../scenarios/paper_dining_room.yaml   # its sensors are replaced by the candidates
//   candidates:
//     axes:                        # every combination
//       type: [laser, ultrasonic, reflectance, ideal]
//       link: [left_tibia, left_thigh]
//       along_m: [-0.35, -0.20]    # along the link's z (its length), from its frame
//       forward_m: 0.06            # in front of the link's axis (one value or a list)
//       pitch_deg: {from: 0, to: 30, step: 15}   # a range: 0, 15, 30 (any axis of numbers, and seeds)
//       yaw_deg: [0]
//     list:                        # and/or mountings one by one
//       - {type: laser, link: right_tibia, xyz_m: [0.06, 0, -0.3], rpy_deg: [0, 10, 0]}
//   scenes:
//     - {name: obstacle_15cm, builtin: dining_room}
//     - {name: obstacle_5cm, builtin: dining_room, obstacle: {height_m: 0.05, x_m: 2.0}}
//     - {name: stairs, builtin: stairs}
//   seeds: [1, 2, 3]
//   hazards: [obstacle, step, hole]   # object-name prefixes; a variant without one has no such hazard
//   select: {sensors: 3, types: [laser, ultrasonic]}   # types: optional, default every type
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace proxsim {

/// One candidate mounting: a sensor of the base's presets, on a link, at a pose.
struct Candidate {
  std::string id;              ///< "laser@left_tibia:z-0.35:x0.06:p15:y0" (unique, stable)
  std::string type;            ///< as the study names it: a sensor type or a part
  SensorConfig sensor;         ///< name = id
  double along_m = 0, forward_m = 0, pitch_deg = 0, yaw_deg = 0;  ///< the axes' values (for the figures)
  Vec3 xyz_m = Vec3::Zero(), rpy_deg = Vec3::Zero();  ///< its pose on the link, as a scenario writes it
};

/// One scene variant: the scenario every candidate runs in.
struct SceneVariant {
  std::string name;
  Scenario scenario;  ///< the base with this variant's scene, without sensors
};

struct StudyConfig {
  std::string source;
  std::vector<Candidate> candidates;
  std::vector<SceneVariant> variants;
  std::vector<std::uint64_t> seeds;
  std::vector<std::string> hazards;  ///< object-name prefixes
  int select_sensors = 3;            ///< k of the greedy selection
  std::vector<std::string> select_types;  ///< the types the selection may pick; empty: every type
};

/// A study's size, bounded before anything is built (issue 23: a study of
/// 1.9 million candidates ended in std::bad_alloc). Every candidate is a
/// sensor in each job's simulation; a run is a candidate in a scene with a seed.
inline constexpr std::size_t kMaxStudyCandidates = 10'000;
inline constexpr std::size_t kMaxStudyRuns = 1'000'000;
/// Even with allow_large: beyond this the candidates alone would not fit in memory.
inline constexpr std::size_t kHardMaxStudyCandidates = 1'000'000;

class YamlReader;
struct Field;

/// The `candidates:` section (axes and/or list), read as a detection study
/// reads it (problems recorded in `reader`); an outcome study combines them.
std::vector<Candidate> ReadStudyCandidates(YamlReader& reader, const Field& field, bool allow_large);

/// A candidate of a sensor type or part on `link` at the axes' values (a row
/// of a detection study's ranking.csv); nullopt for an unknown type or part.
std::optional<Candidate> MakeStudyCandidate(const std::string& type, const std::string& link, double along_m,
                                            double forward_m, double pitch_deg, double yaw_deg);

/// Reads and validates a study; throws InputError listing every problem.
/// `allow_large` (--allow-large) lifts kMaxStudyCandidates and kMaxStudyRuns.
StudyConfig LoadStudyFile(const std::string& path, bool allow_large = false);

}  // namespace proxsim
