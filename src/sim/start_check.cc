#include "sim/start_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "scene/shape_inside.h"
#include "scene/shape_points.h"

namespace proxsim {

namespace {

// A robot surface point deeper than this inside an object overlaps it. The
// soles rest on their support to 1e-9 m and the surface samples lie on the
// links' surfaces, so only a real interpenetration reaches this deep; 5 mm
// also leaves Embree's float rounding (about 1e-6 m here) far behind.
constexpr double kOverlap_m = 0.005;
// A foot stands on the object met within this distance below its lowest point.
constexpr double kStandsOn_m = 0.01;
// The downward probe under a foot starts this far above its lowest point.
constexpr double kProbeAbove_m = 0.05;

std::string Format(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b, c, d);
  return text;
}

std::string QuotedList(const std::vector<std::string>& names) {
  std::string all;
  for (const std::string& name : names) all += (all.empty() ? "'" : ", '") + name + "'";
  return all;
}

// The scene object each foot stands on at t = 0 (−1: none within kStandsOn_m),
// from a vertical ray below the foot's lowest sole point, the robot transparent.
struct FootSupport {
  int foot_link = -1;
  std::int32_t object_id = -1;  // −1: no scene object within kStandsOn_m
  double z_m = 0;               // the surface met
};

std::vector<FootSupport> FootSupports(const World& world, const RobotInScene& robot,
                                                       const std::vector<FootFrame>& feet) {
  std::vector<Ray> rays;
  for (const FootFrame& foot : feet) {
    Vec3 p_W_low = Vec3::Constant(std::numeric_limits<double>::infinity());
    for (const Vec3& p_L : {foot.p_L_heel, foot.p_L_toe, foot.p_L_sole}) {
      const Vec3 p_W = robot.X_WL(foot.link) * p_L;
      if (p_W.z() < p_W_low.z()) p_W_low = p_W;
    }
    rays.push_back({.origin_W = (p_W_low + Vec3(0, 0, kProbeAbove_m)).cast<float>(),
                    .direction_W = -Vec3f::UnitZ(),
                    .max_range_m = static_cast<float>(kProbeAbove_m + kStandsOn_m),
                    .see_robot = false});
  }
  std::vector<Hit> hits(rays.size());
  world.caster().Cast(rays, hits);
  std::vector<FootSupport> supports;
  for (std::size_t i = 0; i < feet.size(); ++i) {
    const bool on_scene = hits[i].is_hit() && hits[i].object_id < world.first_robot_object_id();
    supports.push_back({feet[i].link, on_scene ? hits[i].object_id : -1,
                        static_cast<double>(rays[i].origin_W.z()) - static_cast<double>(hits[i].distance_m)});
  }
  return supports;
}

}  // namespace

std::vector<std::string> StartProblems(const Scenario& scenario, World& world, Locomotion& locomotion) {
  RobotInScene& robot = *world.robot();
  const RobotModel& model = robot.model();
  const std::string where = scenario.source + ": robot.start: ";
  const std::string start_on = scenario.robot ? scenario.robot->start_on : "";
  std::vector<std::string> problems;

  // the robot at t = 0, as the run will have it
  robot.Place(locomotion.Advance(0.0));
  world.caster().Commit();

  // 1. what the feet stand on: the ground, or the object `on` names
  const std::vector<FootFrame> feet = locomotion.Feet();
  std::set<std::int32_t> supports;
  if (locomotion.gait_cycle()) {
    for (const FootSupport& support : FootSupports(world, robot, feet)) {
      if (support.object_id < 0) continue;
      const bool first = supports.insert(support.object_id).second;
      const SceneObject& object = scenario.scene.objects[support.object_id];
      if (!first || object.ground || object.name == start_on) continue;  // one line per object
      problems.push_back(where + "the robot would start standing on object '" + object.name + "' (its foot '" +
                         model.link_name(support.foot_link) + "' on it" + Format(" at z = %.3f m", std::abs(support.z_m) < 5e-4 ? 0.0 : support.z_m /* no "-0.000" */) +
                         "), not on the ground: the gait stands the robot on the surface below its start; start "
                         "it elsewhere, or give `on: " + object.name + "` in robot.start to start on it on purpose");
    }
    if (!start_on.empty()) {
      const auto on = std::ranges::find_if(scenario.scene.objects, [&](const SceneObject& o) { return o.name == start_on; });
      const auto on_id = static_cast<std::int32_t>(on - scenario.scene.objects.begin());
      if (on != scenario.scene.objects.end() && !supports.contains(on_id)) {
        std::vector<std::string> under;
        for (const std::int32_t id : supports) under.push_back(scenario.scene.objects[id].name);
        problems.push_back(where + "on: '" + start_on + "', but the robot's feet at its start " +
                           Format("(%.3f, %.3f) m ", scenario.robot->start_xyz_m.x(), scenario.robot->start_xyz_m.y()) +
                           (under.empty() ? std::string("stand on no object") : "stand on " + QuotedList(under)) +
                           "; place the start above '" + start_on + "' or leave `on` out");
      }
    }
  }

  // 2. the robot's surface inside an object other than its ground: the links
  // that reach into each object, one line per object
  for (std::size_t id = 0; id < scenario.scene.objects.size(); ++id) {
    const SceneObject& object = scenario.scene.objects[id];
    if (object.ground || std::holds_alternative<Plane>(object.shape)) continue;  // a plane has no inside
    // the object's bounding box in its own frame, to skip far points cheaply
    Vec3 lo_O = Vec3::Constant(std::numeric_limits<double>::infinity()), hi_O = -lo_O;
    for (const Vec3& p_O : ShapeOutlinePoints_O(object.shape)) {
      lo_O = lo_O.cwiseMin(p_O);
      hi_O = hi_O.cwiseMax(p_O);
    }
    const Pose X_OW = object.X_WO.inverse();
    std::vector<std::string> links;
    double deepest_m = 0;
    Vec3 p_W_deepest = Vec3::Zero();
    for (int link = 0; link < model.link_count(); ++link) {
      bool inside = false;
      for (const Vec3& p_L : robot.surface_points_L(link)) {
        const Vec3 p_W = robot.X_WL(link) * p_L;
        const Vec3 p_O = X_OW * p_W;
        if ((p_O.array() < lo_O.array() - kOverlap_m).any() || (p_O.array() > hi_O.array() + kOverlap_m).any()) continue;
        const double depth_m = DepthInside_m(object.shape, p_O);
        if (depth_m <= kOverlap_m) continue;
        inside = true;
        if (depth_m > deepest_m) {
          deepest_m = depth_m;
          p_W_deepest = p_W;
        }
      }
      if (inside) links.push_back(model.link_name(link));
    }
    if (links.empty()) continue;
    problems.push_back(where + "the robot starts inside object '" + object.name + "': link" +
                       (links.size() == 1 ? " " : "s ") + QuotedList(links) +
                       (links.size() == 1 ? " reaches" : " reach") +
                       Format(" into it (up to %.3f m deep, at (%.3f, %.3f, ", deepest_m, p_W_deepest.x(),
                              p_W_deepest.y()) +
                       Format("%.3f) m); start the robot clear of it", p_W_deepest.z()));
  }
  locomotion.Reset();
  return problems;
}

}  // namespace proxsim
