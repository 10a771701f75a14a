#include "sim/run_summary.h"

#include <cmath>

#include "raycast/embree_version.h"
#include "scenario/gait_section.h"
#include "scenario/robot_section.h"
#include "sim/params_json.h"
#include "sensors/sensor_echo.h"
#include "sensors/sensor_types.h"
#include "sensors/wave_speed.h"
#include "scene/mesh_loader.h"

namespace proxsim {

namespace {

nlohmann::json NullUnless(bool known, const nlohmann::json& value) { return known ? value : nlohmann::json(nullptr); }

// the strategy's keys by its declaration (strategy/strategy_config.h), and its name
nlohmann::json StrategyJson(const StrategyConfig& config) {
  nlohmann::json echo = std::holds_alternative<StopConfig>(config)
                            ? ParamsJson(StopSchema(), std::get<StopConfig>(config))
                            : ParamsJson(CircumventSchema(), std::get<CircumventConfig>(config));
  echo["name"] = StrategyName(config);
  return echo;
}

}  // namespace

nlohmann::json VersionsJson() {
  return {{"proxsim", PROXSIM_VERSION},
          {"embree", EmbreeVersion()},
          {"embree_config", EmbreeDeviceConfig()},
          {"assimp", AssimpVersion()},
          {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                        std::to_string(EIGEN_MINOR_VERSION)}};
}

nlohmann::json InputsJson(const Scenario& scenario) {
  nlohmann::json sensors = nlohmann::json::array();
  for (const SensorConfig& sensor : scenario.sensors) {
    const Vec3 rpy_deg = RpyFromRotation(sensor.X_LS.linear()) * (180.0 / kPi);
    const Vec3& xyz = sensor.X_LS.translation();
    // the spec's keys from the sensor's home (sensors/sensor_echo.cc), the mounting and timing beside them
    nlohmann::json echo = SensorSpecJson(sensor.spec);
    echo["name"] = sensor.name;
    echo["link"] = sensor.link;
    echo["pose"] = {{"xyz_m", {xyz.x(), xyz.y(), xyz.z()}}, {"rpy_deg", {rpy_deg.x(), rpy_deg.y(), rpy_deg.z()}}};
    echo["see_robot"] = sensor.see_robot;
    echo["rate_hz"] = NullUnless(sensor.rate_hz > 0, sensor.rate_hz);  // null: every sample
    echo["latency_s"] = sensor.latency_s;
    echo["flight_time"] = sensor.flight_time;
    echo["wave_speed_m_s"] = WaveSpeed_m_s(sensor.spec.type, sensor.wave_speed_m_s);
    // as given (a name, or the offset), and the offset it resolved to
    const bool named_schedule = sensor.fire == "simultaneous" || sensor.fire == "round_robin";
    echo["fire"] = named_schedule ? nlohmann::json(sensor.fire) : nlohmann::json(sensor.fire_offset_s);
    echo["fire_offset_s"] = sensor.fire_offset_s;
    echo["crosstalk"] = NullUnless(sensor.spec.type == SensorType::kUltrasonic, sensor.crosstalk);
    sensors.push_back(std::move(echo));
  }
  nlohmann::json objects = nlohmann::json::array();
  for (const SceneObject& object : scenario.scene.objects) objects.push_back(object.name);
  nlohmann::json robot = nullptr;
  if (scenario.robot) {
    const RobotConfig& r = *scenario.robot;
    nlohmann::json waypoints = nlohmann::json::array();
    for (const Vec2& p : r.waypoints_m) waypoints.push_back({p.x(), p.y()});
    // the leg map as given (null: found by the gait), and the joints held at a fixed angle
    nlohmann::json legs = nullptr;
    if (r.legs) {
      legs = nlohmann::json::object();
      for (int side = 0; side < 2; ++side) {
        const LegNames& leg = (*r.legs)[static_cast<std::size_t>(side)];
        legs[side == 0 ? "left" : "right"] = {{"hip", leg.hip}, {"knee", leg.knee}, {"ankle", leg.ankle},
                                              {"foot", leg.foot}, {"ankle_zero_deg", RadToDeg(leg.ankle_zero_rad)}};
      }
    }
    nlohmann::json joints_deg = nlohmann::json::object();
    for (const auto& [joint, q_rad] : r.joints_rad) joints_deg[joint] = RadToDeg(q_rad);
    // the choices and geom_group by their declaration (scenario/robot_section.h), the maps and paths here
    robot = ParamsJson(RobotSectionSchema(), r);
    robot["model"] = r.model;
    robot["package_paths"] = r.package_paths;
    robot["legs"] = legs;
    robot["joints_deg"] = joints_deg;
    robot["start"] = {{"xyz_m", {r.start_xyz_m.x(), r.start_xyz_m.y(), r.start_xyz_m.z()}},
                      {"yaw_deg", RadToDeg(r.start_yaw_rad)},
                      {"on", NullUnless(!r.start_on.empty(), r.start_on)}};
    robot["gait"] = ParamsJson(GaitSectionSchema(), r);
    robot["path"] = {{"waypoints_m", waypoints}};
    robot["strategy"] = r.strategy ? StrategyJson(*r.strategy) : nlohmann::json(nullptr);
    robot["trajectory"] = NullUnless(!r.trajectory_file.empty(), r.trajectory_file);
  }
  nlohmann::json map = nullptr;
  if (scenario.robot) {
    // the map's keys by its declaration (knowledge/terrain_config.h); its sensors, when not given, by the rule
    map = ParamsJson(TerrainMapSchema(), scenario.map);
    if (!scenario.map.sensors_given) map["sensors"] = "types: " + DefaultMapSensorTypes();
  }
  return {{"source", scenario.source},
          {"seed", scenario.seed},
          {"robot", robot},
          {"duration_s", scenario.duration_s},
          {"rate_hz", scenario.rate_hz},
          {"scene", {{"builtin", scenario.builtin_scene},
                     {"objects", objects},
                     {"ambient_klux", scenario.scene.ambient_klux},
                     // what the robot's model file brought (robot.model_scene: include)
                     {"from_model", {{"objects", scenario.scene_from_model.objects},
                                     {"ground_left_out", NullUnless(!scenario.scene_from_model.ground_left_out.empty(),
                                                                    scenario.scene_from_model.ground_left_out)}}}}},
          {"sensors", sensors},
          {"map", map},
          {"outputs", {{"range_convention", scenario.range_convention == RangeConvention::kRep117 ? "rep117" : "proxsim"}}}};
}

nlohmann::json RobotOutcomeJson(const Simulation& sim) {
  const Simulation::RobotOutcome& outcome = sim.robot_outcome();
  const RobotState& state = *sim.robot_state();
  const bool has_goal = sim.scenario().robot && sim.scenario().robot->trajectory_file.empty() &&
                        !sim.scenario().robot->waypoints_m.empty();
  nlohmann::json events = nlohmann::json::array();
  for (const StrategyEvent& event : sim.events()) {
    events.push_back({{"t_s", event.t_s}, {"event", event.event}, {"detail", event.detail}});
  }
  nlohmann::json collisions = nlohmann::json::array();
  for (const auto& c : outcome.collisions) {
    collisions.push_back({{"t_s", c.t_s}, {"link", c.link}, {c.self ? "other_link" : "object", c.object},
                          {"depth_m", c.depth_m}, {"p_W", {c.p_W.x(), c.p_W.y(), c.p_W.z()}}});
  }
  // where the robot fell: the foothold its foot missed, as planned, or (an
  // unsafe step taken under unsafe_steps: fall) the pelvis's point on the ground
  nlohmann::json fall = nullptr;
  if (outcome.fell) {
    fall = {{"t_s", outcome.end_t_s},
            {"p_W", outcome.fall_p_W ? nlohmann::json{outcome.fall_p_W->x(), outcome.fall_p_W->y(), outcome.fall_p_W->z()}
                                     : nlohmann::json(nullptr)},
            {"detail", outcome.end_detail},
            {"reason", outcome.fall_reason}};
  }
  // the gait as walked (null for a replayed or external motion): the
  // ankle zero pitch per leg as used, whether given or found from the soles
  nlohmann::json gait = nullptr;
  if (const auto cycle = sim.locomotion()->gait_cycle()) {
    gait = {{"stride_m", cycle->stride_m},
            {"period_s", cycle->period_s},
            {"crouch_knee_deg", RadToDeg(cycle->crouch_knee_rad)},
            {"pelvis_height_m", cycle->pelvis_height_m},
            {"amplitude", cycle->amplitude},
            {"ankle_zero_deg", {{"left", RadToDeg(cycle->ankle_zero_rad[0])}, {"right", RadToDeg(cycle->ankle_zero_rad[1])}}}};
  }
  const Simulation::Outcome episode = sim.outcome();
  return {{"model", sim.robot()->model().source()},
          {"outcome", episode.name()},
          {"outcome_t_s", episode.t_s},
          {"outcome_detail", episode.detail},
          {"collisions", collisions},
          {"fall", fall},
          {"strategy", sim.strategy() ? nlohmann::json(sim.strategy()->name()) : nlohmann::json(nullptr)},
          {"stopped", outcome.stopped},
          {"stop_t_s", NullUnless(outcome.stopped, outcome.stop_t_s)},
          {"stop_reason", NullUnless(outcome.stopped, outcome.stop_reason)},
          {"stop_requested_t_s", NullUnless(outcome.stop_requested, outcome.stop_request_t_s)},
          {"reached_goal", NullUnless(has_goal, outcome.reached_goal)},
          {"reached_goal_t_s", NullUnless(outcome.reached_goal, outcome.reached_goal_t_s)},
          {"min_clearance_m", NullUnless(std::isfinite(outcome.min_clearance_m), outcome.min_clearance_m)},
          {"min_clearance_t_s", outcome.min_clearance_t_s},
          {"gait", gait},
          {"distance_walked_m", state.distance_walked_m},
          {"standing_at_end", state.stopped},
          {"events", events}};
}

}  // namespace proxsim
