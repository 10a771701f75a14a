#include "scenario/robot_section.h"

namespace proxsim {

const ConfigSchema<RobotConfig>& RobotSectionSchema() {
  using C = RobotConfig;
  static const ConfigSchema<C> schema = [] {
    return ConfigSchema<C>{
        ByHandParam<C>("model", "`builtin:biped` or a path", "`builtin:biped`",
                       "the robot: the built-in biped, a URDF file (with its meshes) or a MuJoCo model, MJCF "
                       "(`<mujoco>`: [robots.md](robots.md#mujoco-models-mjcf))"),
        WithGlosses(
            ChoiceParam<C, ModelScene>(
                "model_scene", &C::model_scene, {{ModelScene::kInclude, "include"}, {ModelScene::kIgnore, "ignore"}},
                "MJCF only: a scene file that includes the robot (MuJoCo Menagerie's `scene.xml`) has geoms of its "
                "own on the world body, a floor and furniture: `include` adds them to the scene as objects "
                "`model:GEOM` (the floor plane only when the scene has no ground of its own), `ignore` leaves them "
                "out ([robots.md](robots.md#a-scene-file-that-includes-the-robot))"),
            {"the world geoms of the model's file join the scene", "the scene is the scenario's alone"}),
        WithNote(AsWhole(ConvertedNumberParam<C>(
                     "geom_group", Between(0, 5), "", "every geom",
                     "MJCF only: the geom group whose geoms are the robot's surface (MuJoCo Menagerie: 2 visual, 3 "
                     "collision)",
                     [](const C& c) { return static_cast<double>(c.geom_group); },
                     [](C& c, double v) { c.geom_group = static_cast<int>(v); },
                     [](const C& c) { return c.geom_group < 0; })),
                 "a MuJoCo geom group"),
        ChoiceParam<C, LinkGeometryKind>(
            "geometry", &C::geometry, {{LinkGeometryKind::kVisual, "visual"}, {LinkGeometryKind::kCollision, "collision"}},
            "which of the URDF's geometries is the robot's surface: what sensors see, the clearance, the soles, the "
            "viewer"),
        ByHandParam<C>("package_paths", "list of folders", "none",
                       "where `package://NAME/...` mesh URIs are looked for first"),
        ByHandParam<C>("legs", "`{left: {hip, knee, ankle, foot, ankle_zero_deg}, right: {...}}`", "the biped's names",
                       "the joints the gait drives (hip, knee and ankle pitch) and the foot link, per leg; all eight "
                       "names required when given. `ankle_zero_deg` in [−45, 45]: the foot's pitch at joint zero (toe "
                       "up positive), for a sole that is not flat there: the gait reads the foot turned flat about the "
                       "ankle and walks it flat; not given, 0, or, for a foot with no sole at 0, the pitch its geometry "
                       "lies flattest at ([robots.md](robots.md#your-own-robot))"),
        ByHandParam<C>("joints_deg", "`{JOINT: angle}`, degrees", "every other joint at 0",
                       "angles held by the joints the gait does not drive (arms, hip roll…)"),
        ByHandParam<C>("start", "`{xyz_m: [x, y, z], yaw_deg, on}`", "origin, 0, the ground",
                       "where the walk starts: the pelvis above (x, y), z the floor height there, heading yaw; `on: "
                       "OBJECT` to start standing on that scene object on purpose (below)"),
        ByHandParam<C>("gait", "map", "scaled to the legs",
                       "the gait's pace and shape, what the legs do with a step they cannot take, and what they plan "
                       "their footholds on: every key in [the table below](#the-gait-section)"),
        WithGlosses(ChoiceParam<C, OnCollision>("on_collision", &C::on_collision,
                                                {{OnCollision::kStop, "stop"}, {OnCollision::kContinue, "continue"}},
                                                "a contact of the robot's body with the world or itself: `stop` ends "
                                                "the episode at the first one, `continue` logs each and walks on "
                                                "([outcomes.md](outcomes.md))"),
                    {"the episode ends at the first collision", "every collision is logged and the walk goes on"}),
        ByHandParam<C>("path", "`{waypoints_m: [[x, y], ...]}`", "straight ahead",
                       "the path to follow on the floor, with or without the start point; the robot stops at the last "
                       "waypoint"),
        ByHandParam<C>("strategy", "`{name: stop \\| circumvent, ...}`", "none",
                       "the built-in strategy that drives the robot from its readings (below)"),
        ByHandParam<C>("stop_distance_m", "number > 0, m", "—",
                       "shorthand for `strategy: {name: stop, stop_distance_m: D}`; not together with `strategy`"),
        ByHandParam<C>("trajectory", "a CSV path", "none", "replay a recorded motion instead of the gait (below)"),
        WithGlosses(
            ChoiceParam<C, LocomotionSource>(
                "locomotion", &C::locomotion,
                {{LocomotionSource::kGait, "gait"}, {LocomotionSource::kExternal, "external"}},
                "what moves the robot: its own gait (or the `trajectory` when given), or `external`: another "
                "simulator sets its state every sample from Python or C++ (co-simulation, "
                "[cosimulation.md](cosimulation.md)); not together with `trajectory`; `proxsim run` and studies refuse "
                "it (exit 2: they have no caller)"),
            {"its own gait, or the trajectory when given",
             "the caller sets the robot's state every sample: docs/cosimulation.md"}),
    };
  }();
  return schema;
}

}  // namespace proxsim
