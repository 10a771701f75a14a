// The baselines an outcome study runs beside the candidate sets, on the same
// worlds and seeds, with the same strategies (docs/studies.md "Baselines"):
//
//  - blind: no sensors at all; the strategy never sees anything. Where the
//    worlds test sensing, it must fail: its success is what a set gets for
//    free.
//  - oracle: perfect perception for the same strategy — its map holds the
//    scene's true heights within kOracleReach_m ahead (map.truth_within_m,
//    sim/truth_map_feed.h), its legs plan on the true ground where a set's
//    would plan on their map (GiveOraclePerception), and a strategy reading
//    each reading reads a dense fan of `ideal` rays (noise-free, exact, any
//    incidence, blind to the robot's own body) from the robot's root link,
//    covering the ground from 0.3 m to 3 m ahead and 60 degrees to either
//    side, ten times a second. Its failures are the strategy's and the
//    legs', not the sensors': its success is what perfect sensing would buy.
//
// A set's perception score is where it lies between the two
// (outcome_stats.h, PerceptionScore).
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "study/outcome_config.h"

namespace proxsim {

inline constexpr const char* kBlindBaseline = "blind";
inline constexpr const char* kOracleBaseline = "oracle";

/// The oracle's fan: azimuths from -kOracleHalfFan_deg to +kOracleHalfFan_deg every
/// kOracleAzimuthStep_deg, each at the pitches whose rays from 1 m up meet
/// the floor at kOracleGroundReach_m.
inline constexpr double kOracleHalfFan_deg = 60;
inline constexpr double kOracleAzimuthStep_deg = 4;
inline constexpr double kOracleRate_hz = 10;
inline constexpr double kOracleRange_m = 4;

/// The baseline sets by name ("blind", "oracle"), as SensorSets (their
/// `baseline` set, no price): what LoadOutcomeStudyFile appends to the sets.
SensorSet BaselineSet(const std::string& name);

/// How far around the robot the oracle's map holds the scene's truth.
inline constexpr double kOracleReach_m = 3;
/// The oracle's map holds surfaces up to this height above the ground the
/// robot stands on (map.max_height_m, if the scenario's is lower): above a
/// pelvis, so a table top that overhangs the path at thigh height is seen.
inline constexpr double kOracleMapCeiling_m = 1.2;

/// Makes a run's scenario the oracle's (its sensors are already the fan):
/// for a strategy that reads the map (perception: map), its map filled from
/// the scene's truth within kOracleReach_m of the robot (map.truth_within_m)
/// up to kOracleMapCeiling_m, and no sensor (the fan feeds only the
/// readings-mode strategies, not the map), and, where the legs plan on the robot's map (gait.footholds: map),
/// legs on the true ground that stand before a step they cannot take — what
/// legs planning on a perfect map do.
void GiveOraclePerception(YAML::Node& run);

/// The sensors a set's runs with `strategy` use, as its rows name them: the
/// set's own, or for the oracle with a strategy that reads the map (whose
/// runs cast no sensor: GiveOraclePerception) one name for its perfect map.
std::vector<std::string> SensorsOfRuns(const SensorSet& set, const StrategyChoice& strategy);

/// Whether `name` is a baseline's.
bool IsBaselineName(const std::string& name);

}  // namespace proxsim
