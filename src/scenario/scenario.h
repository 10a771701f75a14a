// A scenario: everything a run needs, parsed from YAML (docs/scenario.md) and
// validated before anything runs. SI units; angles are degrees in
// the file and radians in these structs.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gait/gait_config.h"
#include "robot/robot_model.h"
#include "robot/urdf_options.h"
#include "scene/scene.h"
#include "sensors/sensor_spec.h"
#include "strategy/strategy_config.h"

namespace YAML {
class Node;
}
#include "knowledge/terrain_config.h"

namespace proxsim {

struct SensorConfig {
  std::string name;
  SensorSpec spec;
  std::string link = "world";    ///< a robot link, or "world"
  int link_line = 0;             ///< line of `link:` in the scenario file, for messages (0: none)
  Pose X_LS = Pose::Identity();  ///< sensor frame S in its link L; the beam is S's +x
  bool see_robot = true;         ///< false: the robot's own links are transparent to this sensor
  // timing (beyond the paper, docs/sensors.md; all off by default)
  double rate_hz = 0.0;          ///< > 0: samples only at the first run sample of each of its periods; 0: every sample
  double latency_s = 0.0;        ///< >= 0: a reading is reported (and seen by the strategy) this much later
  bool flight_time = false;      ///< time of flight: the echo is received where the sensor is when it returns
  double wave_speed_m_s = 0.0;   ///< c for flight_time; 0: 343 m/s for ultrasonic, 299 792 458 m/s otherwise
  // when it pings (ultrasonic sensors hear each other's pings: sensors/crosstalk.h)
  std::string fire = "simultaneous";  ///< `fire` as given: simultaneous, round_robin, or an offset in seconds
  double fire_offset_s = 0.0;    ///< its periods start this long after t = 0 (round_robin: its slot's), in [0, 1/rate_hz)
  bool crosstalk = true;         ///< ultrasonic: it hears other ultrasonic sensors' pings in its listening window
};

/// A robot: what its walk needs (gait/gait_config.h) plus the model it is
/// built from and what drives it.
/// `gait.unsafe_steps`: what a step the legs cannot take does (docs/outcomes.md).
enum class UnsafeSteps {
  kFall,    ///< it is taken: the robot falls there and the episode ends (default)
  kRefuse,  ///< the legs stand before it (`cannot_step`), the episode goes on
};
/// `gait.footholds`: what the footsteps are planned on (docs/terrain.md).
enum class Footholds {
  kTruth,  ///< the scene's true surface: perfect foot placement (default)
  kMap,    ///< the robot's own terrain map; the true surface then decides each landing (gait/touchdown.h)
};
/// `robot.on_collision`: what a contact of the robot's body with the world does.
enum class OnCollision {
  kStop,      ///< the episode ends at the first one (default)
  kContinue,  ///< every one is logged and the walk goes on
};

/// `robot.model_scene`: what becomes of the world geoms of an MJCF that
/// includes the robot (a scene file such as Menagerie's scene.xml).
enum class ModelScene {
  kInclude,  ///< they join the scene as objects `model:GEOM`; the ground plane only when the scene has no ground (default)
  kIgnore,   ///< the scene is the scenario's alone
};

/// `robot.locomotion`: what moves the robot.
enum class LocomotionSource {
  kGait,      ///< its own kinematic gait, or the recorded `trajectory` when given (default)
  kExternal,  ///< the caller sets its state every sample (co-simulation, gait/external_drive.h)
};

struct RobotConfig : WalkConfig {
  UnsafeSteps unsafe_steps = UnsafeSteps::kFall;
  Footholds footholds = Footholds::kTruth;
  int footholds_line = 0;  ///< line of `gait.footholds` in the file, for messages (0: none)
  OnCollision on_collision = OnCollision::kStop;
  std::string model = "builtin:biped";  ///< "builtin:biped" or a URDF path (relative to the scenario file)
  std::optional<StrategyConfig> strategy;  ///< the built-in strategy (`robot.strategy`, or `stop_distance_m` for stop); none when absent
  std::string trajectory_file;              ///< recorded trajectory CSV to replay instead of the gait
  LocomotionSource locomotion = LocomotionSource::kGait;
  LinkGeometryKind geometry = LinkGeometryKind::kVisual;  ///< `robot.geometry`: what the links' surfaces are made of
  std::vector<std::string> package_paths;   ///< `robot.package_paths`: folders for package:// URIs (resolved paths)
  int geom_group = -1;                      ///< `robot.geom_group` (MJCF): the geom group of the links' surfaces; −1 every geom
  /// `robot.start.on`: the scene object the robot starts standing on, on purpose
  /// (empty: it starts on the ground); checked to exist when the scenario loads
  std::string start_on;
  ModelScene model_scene = ModelScene::kInclude;  ///< `robot.model_scene`
  /// An MJCF model as the scenario read it, to take its scene: the run walks
  /// this one while ModelReadKey still gives model_read_key (null: read at the run)
  std::shared_ptr<const RobotModel> model_read;
  std::string model_read_key;
};

/// What a robot model is read from and with (the file and its geometry
/// options), as text: equal keys read the same model.
std::string ModelReadKey(const RobotConfig& robot);

/// What the scene took from the robot's model file (`robot.model_scene: include`).
struct SceneFromModel {
  std::vector<std::string> objects;  ///< the scene objects it added, in scene order
  /// the model's ground plane (its geom name), left out: the scene has a ground of its own
  std::string ground_left_out;
};

/// `outputs.range_convention`: how readings.csv's d_m states a reading that is not a detection.
enum class RangeConvention {
  kProxsim,  ///< the paper's: d_m = the maximum range, the status says why (default)
  kRep117,   ///< ROS REP 117 / sensor_msgs/Range: −Inf too close, +Inf nothing in range, NaN invalid; plus variance_m2
};

struct Scenario {
  std::string source;  ///< the file it came from ("builtin:NAME" for embedded ones)
  int schema = 1;
  std::uint64_t seed = 1;
  double duration_s = 10.0;  ///< > 0
  double rate_hz = 50.0;     ///< samples per second, > 0
  std::string builtin_scene = "empty";
  Scene scene;  ///< the built-in scene's objects followed by the file's own (then the robot model's), meshes loaded
  SceneFromModel scene_from_model;  ///< the objects of `scene` that came from the robot's model file
  std::optional<RobotConfig> robot;
  std::vector<SensorConfig> sensors;
  TerrainMapConfig map;  ///< `map`: the terrain map a robot builds (defaults without the section)
  RangeConvention range_convention = RangeConvention::kProxsim;  ///< `outputs.range_convention`

  /// Number of samples in the run: t_k = k / rate_hz for k in [0, count).
  std::int64_t SampleCount() const;
};

/// Parses and validates a scenario file. Throws InputError listing every
/// problem (file, line, key, expectation; unknown keys with the nearest valid
/// key suggested). Mesh and URDF paths are resolved relative to the file.
Scenario LoadScenarioFile(const std::string& path);

/// The same from YAML text; `source` names it in messages and resolves relative paths.
Scenario LoadScenarioText(const std::string& yaml_text, const std::string& source);

/// The same from a parsed document (a closed-loop study's episode, built as a
/// node: study/outcome_config.h); messages name `source` without line numbers
/// for what the document did not bring from a text.
Scenario LoadScenarioNode(YAML::Node document, const std::string& source);

/// Names of the built-in scenarios ("paper" is the default run).
std::vector<std::string> BuiltinScenarioNames();

/// A built-in scenario by name: "paper" (the paper's experiment), "world_demo".
Scenario LoadBuiltinScenario(const std::string& name);

}  // namespace proxsim
