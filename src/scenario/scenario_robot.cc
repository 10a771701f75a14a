// The `robot` section: which robot (the built-in biped or a URDF file), which
// of its geometries stands for its surface and where its package:// meshes
// are, how the gait maps onto its legs and which angles its other joints
// hold, where it starts, how it walks (gait, path of waypoints, or a recorded trajectory)
// and its built-in strategy (`strategy: {name: stop | circumvent, ...}`, or
// the shorthand `stop_distance_m: D` for `{name: stop, stop_distance_m: D}`). The URDF itself is loaded elsewhere
// (robot/); here we only check that a named file exists, so that a typo in a
// path is reported with the scenario's other problems.
#include <algorithm>
#include <memory>
#include <set>
#include <system_error>
#include <tuple>

#include "core/input_error.h"
#include "core/nearest_key.h"
#include "robot/mjcf_model.h"
#include "scenario/gait_section.h"
#include "scenario/param_reader.h"
#include "scenario/robot_section.h"
#include "scenario/scenario_sections.h"

namespace proxsim {


namespace {

constexpr const char* kBuiltinPrefix = "builtin:";

// A file path value: resolved against the scenario's folder, and required to exist.
std::optional<std::string> ReadExistingFile(YamlReader& reader, const Field& field,
                                            const std::filesystem::path& base_dir, const std::string& what) {
  const auto text = reader.String(field);
  if (!text) return std::nullopt;
  const std::filesystem::path path = ResolveScenarioPath(base_dir, *text);
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    reader.Fail(field, "expected " + what + " (relative paths start from the scenario's folder), but '" +
                           path.string() + "' is not a file");
    return std::nullopt;
  }
  return path.string();
}

// legs: {left: {hip, knee, ankle, foot}, right: {...}}, every name required
std::optional<std::array<LegNames, 2>> ReadLegs(YamlReader& reader, const Field& field) {
  if (!field) return std::nullopt;
  const auto legs = reader.Map(field, {"left", "right"});
  if (!legs) return std::nullopt;
  std::array<LegNames, 2> names;
  bool complete = true;
  for (const auto& [side, leg] : {std::pair{"left", &names[0]}, std::pair{"right", &names[1]}}) {
    const Field side_field = (*legs)[side];
    if (!reader.Require(side_field, std::string(side) + ": {hip, knee, ankle, foot}, the leg's joints and foot link")) {
      complete = false;
      continue;
    }
    const auto map = reader.Map(side_field, {"hip", "knee", "ankle", "foot", "ankle_zero_deg"});
    if (!map) {
      complete = false;
      continue;
    }
    for (const auto& [key, value, what] :
         {std::tuple{"hip", &leg->hip, "the hip pitch joint's name"}, std::tuple{"knee", &leg->knee, "the knee joint's name"},
          std::tuple{"ankle", &leg->ankle, "the ankle pitch joint's name"}, std::tuple{"foot", &leg->foot, "the foot link's name"}}) {
      const Field name = (*map)[key];
      const auto text = reader.Require(name, std::string(key) + ", " + what) ? reader.String(name) : std::nullopt;
      if (text) *value = *text;
      else complete = false;
    }
    // a foot pitched at joint zero: its pitch there, toe up positive
    if (const auto zero = reader.Number((*map)["ankle_zero_deg"], NumberIn(-45.0, 45.0, "deg"))) {
      leg->ankle_zero_rad = DegToRad(*zero);
      leg->ankle_zero_given = true;
    }
  }
  if (!complete) return std::nullopt;
  return names;
}

// joints_deg: {JOINT: angle, ...}, any joint names (checked against the URDF when it loads)
std::vector<std::pair<std::string, double>> ReadJointAngles(YamlReader& reader, const Field& field) {
  std::vector<std::pair<std::string, double>> angles;
  if (!field || field.node.IsNull()) return angles;
  if (!field.node.IsMap()) {
    reader.Fail(field, "expected a map {JOINT_NAME: angle in degrees, ...}, got " + DescribeNode(field.node));
    return angles;
  }
  for (const auto& entry : field.node) {
    const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : "";
    const Field value{entry.second, JoinPath(field.path, name), true};
    if (name.empty()) {
      reader.Fail(value, "expected a joint name as the key");
      continue;
    }
    if (std::ranges::any_of(angles, [&](const auto& a) { return a.first == name; })) {
      reader.Fail(value, "joint '" + name + "' is given twice");
      continue;
    }
    if (const auto deg = reader.Number(value, AnyNumber())) angles.emplace_back(name, DegToRad(*deg));
  }
  return angles;
}


// one strategy's map by its declaration (strategy/strategy_config.h), `name` aside
template <class Config>
std::optional<StrategyConfig> ReadStrategySection(YamlReader& reader, const Field& field,
                                                  const ConfigSchema<Config>& schema) {
  const auto map = OpenSection(reader, field, schema, {"name"});
  if (!map) return std::nullopt;
  Config config;
  ReadParams(reader, *map, schema, config);
  const StrategyConfig strategy = config;
  ReportAtKeys(reader, *map, Validate(strategy));
  return strategy;
}

// The world geoms of an MJCF that includes the robot (a scene file), read
// with the model now: added to the scene as objects `model:GEOM` after its
// own, the ground plane only when the scene has no ground yet (else left out:
// the scene's ground stands for it). The model read is kept for the run (a
// scenario is read again for each run of a study: its robot's own file is not
// compiled then, only a file whose text may give the world body geoms).
void TakeModelScene(YamlReader& reader, const Field& model_field, RobotConfig& robot, Scene& scene,
                    SceneFromModel& from_model) {
  if (robot.model.empty() || robot.model.starts_with(kBuiltinPrefix) || !RobotModel::IsMjcfFile(robot.model)) return;
  // (a robot's own file, without world geoms, is read once, when the run builds it)
  if (robot.model_scene == ModelScene::kIgnore || !MjcfMayHaveWorldGeoms(robot.model)) return;
  const UrdfOptions options{.geometry = robot.geometry, .package_paths = robot.package_paths, .geom_group = robot.geom_group};
  try {
    robot.model_read = std::make_shared<const RobotModel>(RobotModel::FromMjcfFile(robot.model, options));
    robot.model_read_key = ModelReadKey(robot);
  } catch (const InputError&) {
    return;  // the robot's own problems, reported where it is built (with the scenario's, or by the run)
  }
  bool has_ground = std::ranges::any_of(scene.objects, [](const SceneObject& o) { return o.ground; });
  std::set<std::string> names;
  for (const SceneObject& object : scene.objects) names.insert(object.name);
  for (const ModelSceneGeom& geom : robot.model_read->scene_geoms()) {
    if (!geom.problem.empty()) {
      reader.Fail(model_field, "geom '" + geom.geom + "' of the model's world body (its scene) is " + geom.problem +
                                   "; or leave the model's scene out: robot.model_scene: ignore");
      continue;
    }
    if (geom.ground_plane && has_ground) {
      from_model.ground_left_out = geom.geom;
      continue;
    }
    has_ground = has_ground || geom.ground_plane;
    for (const SceneObject& object : geom.objects) {
      if (!names.insert(object.name).second) {
        reader.Fail(model_field, "geom '" + geom.geom + "' of the model's world body becomes scene object '" +
                                     object.name + "', a name the scene already uses; rename one");
        continue;
      }
      scene.objects.push_back(object);
      from_model.objects.push_back(object.name);
    }
  }
}

}  // namespace

std::string ModelReadKey(const RobotConfig& robot) {
  std::string key = robot.model + '\n' + std::to_string(static_cast<int>(robot.geometry)) + '\n' +
                    std::to_string(robot.geom_group);
  for (const std::string& path : robot.package_paths) key += '\n' + path;
  return key;
}

std::optional<StrategyConfig> ReadStrategy(YamlReader& reader, const Field& field) {
  const std::vector<std::string> names = {"stop", "circumvent"};
  const YAML::Node name_node = field.node.IsMap() ? field.node["name"] : YAML::Node();
  const std::string name = name_node && name_node.IsScalar() ? name_node.Scalar() : "";
  if (name == "stop") return ReadStrategySection<StopConfig>(reader, field, StopSchema());
  if (name == "circumvent") return ReadStrategySection<CircumventConfig>(reader, field, CircumventSchema());
  // not a map, no name, or an unknown one
  if (!field.node.IsMap()) {
    reader.Fail(field, "expected a map {name: stop | circumvent, ...}, got " + DescribeNode(field.node));
  } else if (!name_node) {
    reader.Fail(field, "expected a strategy name: name: stop or name: circumvent");
  } else {
    const auto nearest = NearestKey(name, names);
    reader.Fail(field, "unknown strategy '" + name + "'" + (nearest ? " (did you mean '" + *nearest + "'?)" : "") +
                           "; expected stop or circumvent");
  }
  return std::nullopt;
}

RobotConfig ReadRobot(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir, Scene& scene,
                      SceneFromModel& from_model) {
  RobotConfig robot;
  const auto map = OpenSection(reader, field, RobotSectionSchema());
  if (!map) return robot;
  // geometry, geom_group, model_scene, on_collision, locomotion: by their declaration (robot_section.h)
  ReadParams(reader, *map, RobotSectionSchema(), robot);
  ReportAtKeys(reader, *map, CheckParamBounds(RobotSectionSchema(), robot));

  // model: builtin:NAME, or a URDF or MJCF file
  const Field model = (*map)["model"];
  if (model && model.node.IsScalar() && model.node.Scalar().starts_with(kBuiltinPrefix)) {
    robot.model = model.node.Scalar();
  } else if (const auto urdf = ReadExistingFile(reader, model, base_dir, "builtin:biped or the path of a URDF or MJCF file")) {
    robot.model = *urdf;
  }

  // package_paths: [folder, ...], relative to the scenario's folder
  if (const auto folders = reader.List((*map)["package_paths"], "a list of folders holding ROS packages")) {
    for (const Field& folder : *folders) {
      const auto text = reader.String(folder);
      if (!text) continue;
      const std::filesystem::path path = ResolveScenarioPath(base_dir, *text);
      std::error_code error;
      if (!std::filesystem::is_directory(path, error)) {
        reader.Fail(folder, "expected a folder (relative paths start from the scenario's folder), but '" +
                                path.string() + "' is not one");
        continue;
      }
      robot.package_paths.push_back(path.string());
    }
  }

  // (before start.on, which may name one of them)
  TakeModelScene(reader, model, robot, scene, from_model);

  robot.legs = ReadLegs(reader, (*map)["legs"]);
  robot.joints_rad = ReadJointAngles(reader, (*map)["joints_deg"]);

  // start: {xyz_m, yaw_deg, on}; `on` names the object the robot starts on
  // on purpose (sim/start_check.h refuses any other start on or in an object)
  if (const auto start = reader.Map((*map)["start"], {"xyz_m", "yaw_deg", "on"})) {
    robot.start_xyz_m = reader.Vector3((*start)["xyz_m"], Coordinate(), "[x, y, z] in metres").value_or(robot.start_xyz_m);
    robot.start_yaw_rad = DegToRad(reader.Number((*start)["yaw_deg"]).value_or(0.0));
    if (const Field on = (*start)["on"]) {
      if (const auto object = reader.String(on)) {
        std::vector<std::string> names;
        for (const SceneObject& o : scene.objects) names.push_back(o.name);
        const auto named = std::ranges::find(names, *object);
        if (named != names.end() && scene.objects[named - names.begin()].motion) {
          // feet stand only on what stands still: the gait plants them in the world, not on a moving box
          reader.Fail(on, "'" + *object + "' moves (its motion key); the robot can start only on an object that "
                                          "stands still");
        } else if (named != names.end()) {
          robot.start_on = *object;
        } else {
          const auto nearest = NearestKey(*object, names);
          reader.Fail(on, "no object '" + *object + "' in the scene" +
                              (nearest ? " (did you mean '" + *nearest + "'?)" : "") +
                              "; expected the name of the object the robot starts on");
        }
      }
    }
  }

  // gait: by its declaration (gait_section.h); stride or period absent scale
  // with the legs, max_step_m absent comes from them
  robot.gait.derive_stride_from_legs = robot.gait.derive_period_from_legs = true;
  if (const auto gait = OpenSection(reader, (*map)["gait"], GaitSectionSchema())) {
    ReadParams(reader, *gait, GaitSectionSchema(), robot);
    ReportAtKeys(reader, *gait, CheckParamBounds(GaitSectionSchema(), robot));
    if (const Field footholds = (*gait)["footholds"]) robot.footholds_line = footholds.node.Mark().line + 1;
  }

  // path: {waypoints_m: [[x, y], ...]}
  if (const auto path = reader.Map((*map)["path"], {"waypoints_m"})) {
    if (const auto points = reader.List((*path)["waypoints_m"], "a list of [x, y] points in metres")) {
      for (const Field& point : *points) {
        if (const auto xy = reader.Numbers(point, 2, Coordinate(), "[x, y] in metres")) {
          robot.waypoints_m.emplace_back((*xy)[0], (*xy)[1]);
        }
      }
    }
  }

  // the strategy, or its shorthand for stop
  const Field shorthand = (*map)["stop_distance_m"];
  const Field strategy = (*map)["strategy"];
  if (shorthand && strategy) {
    reader.Fail(shorthand, "give either stop_distance_m (shorthand for strategy: {name: stop, stop_distance_m: D}) "
                           "or strategy, not both");
  } else if (strategy) {
    robot.strategy = ReadStrategy(reader, strategy);
  } else if (const auto stop_distance_m = reader.Number(shorthand, PositiveNumber("m"))) {
    robot.strategy = StopConfig{.stop_distance_m = *stop_distance_m};
  }
  if (const Field trajectory = (*map)["trajectory"]) {
    robot.trajectory_file = ReadExistingFile(reader, trajectory, base_dir, "the path of a joint trajectory CSV file")
                                .value_or("");
  }

  // locomotion: external (co-simulation: the caller sets the state every sample) replays nothing
  if (robot.locomotion == LocomotionSource::kExternal && (*map)["trajectory"]) {
    reader.Fail((*map)["locomotion"], "give either locomotion: external or a trajectory to replay, not both");
  }
  return robot;
}

}  // namespace proxsim
