#include "sim/start_check.h"
#include "core/message_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include "scene/shape_inside.h"


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
    // a surface facing down was met from within an object: nothing stands on that
    const bool on_scene = hits[i].is_hit() && hits[i].object_id < world.first_robot_object_id() &&
                          hits[i].normal_W.z() > 0;
    supports.push_back({feet[i].link, on_scene ? hits[i].object_id : -1,
                        static_cast<double>(rays[i].origin_W.z()) - static_cast<double>(hits[i].distance_m)});
  }
  return supports;
}

// The links of the robot whose surface reaches more than kOverlap_m into a
// scene object that is not ground, by object. Each surface sample casts a
// ray up and one down (the robot transparent): when the first surface met is
// an object's inside (its normal along the ray: met from within), the sample
// is inside that object, as deep as its distance to that object's surface
// (scene/shape_inside.h for a box, sphere or cylinder; the caster's distance
// to the triangles for a mesh). Embree keeps this fast on meshes of any size.
// (An object nested in another can hide the outer one from both rays; the
// inner one is still found.)
struct ObjectOverlap {
  std::int32_t object_id = -1;
  std::set<int> links;  // by index: model order
  double deepest_m = 0;
  Vec3 p_W_deepest = Vec3::Zero();
};

// Whether any point in the box [lo, hi] (W) may lie inside a scene object
// that is not ground (in the caster at its scenario pose, as before any
// sample): a solid whose own box (in its frame O) the box's corners, taken
// into O, clear holds none of them, so no ray of Overlaps can find them
// inside it. A mesh that is not ground (found inside by the distance to its
// triangles, once met from within) always may.
bool MayBeInsideAnObject(const Scenario& scenario, const Vec3& lo, const Vec3& hi) {
  // far above the rounding of the samples' and the objects' poses
  constexpr double kSlack_m = 1e-6;
  for (const SceneObject& object : scenario.scene.objects) {
    if (object.ground || std::holds_alternative<Plane>(object.shape)) continue;  // as Overlaps
    Vec3 half_O = Vec3::Zero();
    if (const auto* box = std::get_if<Box>(&object.shape)) half_O = box->size_m / 2;
    else if (const auto* sphere = std::get_if<Sphere>(&object.shape)) half_O = Vec3::Constant(sphere->radius_m);
    else if (const auto* cylinder = std::get_if<Cylinder>(&object.shape))
      half_O = Vec3(cylinder->radius_m, cylinder->radius_m, cylinder->length_m / 2);
    else return true;  // a mesh
    const Pose X_OW = object.X_WO.inverse();
    Vec3 lo_O = Vec3::Constant(std::numeric_limits<double>::infinity()), hi_O = -lo_O;
    for (int corner = 0; corner < 8; ++corner) {
      const Vec3 p_O = X_OW * Vec3(corner & 1 ? hi.x() : lo.x(), corner & 2 ? hi.y() : lo.y(), corner & 4 ? hi.z() : lo.z());
      lo_O = lo_O.cwiseMin(p_O);
      hi_O = hi_O.cwiseMax(p_O);
    }
    if ((lo_O.array() <= half_O.array() + kSlack_m).all() && (hi_O.array() >= -half_O.array() - kSlack_m).all())
      return true;
  }
  return false;
}

std::vector<ObjectOverlap> Overlaps(const Scenario& scenario, const World& world, const RobotInScene& robot) {
  std::vector<Vec3> p_W;
  std::vector<int> link_of;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int link = 0; link < robot.model().link_count(); ++link) {
    for (const Vec3& p_L : robot.surface_points_L(link)) {
      p_W.push_back(robot.X_WL(link) * p_L);
      link_of.push_back(link);
      lo = lo.cwiseMin(p_W.back());
      hi = hi.cwiseMax(p_W.back());
    }
  }
  // (a robot whose box clears every solid's box casts none of its ~10 000 rays)
  if (p_W.empty() || !MayBeInsideAnObject(scenario, lo, hi)) return {};
  std::vector<Ray> rays;
  for (const Vec3& p : p_W) {
    for (const float dz : {1.0f, -1.0f}) {
      rays.push_back(
          {.origin_W = p.cast<float>(), .direction_W = Vec3f(0, 0, dz), .max_range_m = 1e4f, .see_robot = false});
    }
  }
  std::vector<Hit> hits(rays.size());
  world.caster().Cast(rays, hits);
  std::map<std::int32_t, ObjectOverlap> by_object;
  std::map<std::int32_t, std::vector<std::int32_t>> all_but;  // DistanceToWorld's exclude list: every other object
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const Hit& hit = hits[r];
    if (!hit.is_hit() || hit.object_id >= world.first_robot_object_id()) continue;
    const SceneObject& object = scenario.scene.objects[hit.object_id];
    if (object.ground || std::holds_alternative<Plane>(object.shape)) continue;  // a plane has no inside
    if (hit.normal_W.dot(rays[r].direction_W) <= 0) continue;  // met from outside
    const Vec3& p = p_W[r / 2];
    double depth_m = 0;
    if (std::holds_alternative<Mesh>(object.shape)) {
      // a mesh's distance is to its triangles (Embree's point query: fast on any mesh)
      auto [others, fresh] = all_but.try_emplace(hit.object_id);
      if (fresh) {
        for (std::int32_t id = 0; id < world.first_robot_object_id(); ++id)
          if (id != hit.object_id) others->second.push_back(id);
      }
      depth_m = world.caster().DistanceToWorld(p, others->second);
    } else {
      // the caster's distance to a solid is 0 inside it: the closed form instead
      depth_m = DepthInside_m(object.shape, object.X_WO.inverse() * p);
    }
    if (depth_m <= kOverlap_m) continue;
    ObjectOverlap& overlap = by_object[hit.object_id];
    overlap.object_id = hit.object_id;
    overlap.links.insert(link_of[r / 2]);
    if (depth_m > overlap.deepest_m) {
      overlap.deepest_m = depth_m;
      overlap.p_W_deepest = p;
    }
  }
  std::vector<ObjectOverlap> overlaps;
  for (auto& [id, overlap] : by_object) overlaps.push_back(std::move(overlap));
  return overlaps;
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
      const double z_m = std::abs(support.z_m) < 5e-4 ? 0.0 : support.z_m;  // no "-0.000"
      problems.push_back(where + "the robot would start standing on object '" + object.name + "' (its foot '" +
                         model.link_name(support.foot_link) + "' on it" + FormatNumbers(" at z = %.3f m", z_m) +
                         "), not on the ground: the gait stands the robot on the surface below its start; start "
                         "it elsewhere, or give `on: " + object.name + "` in robot.start to start on it on purpose");
    }
    if (!start_on.empty()) {
      const auto on =
          std::ranges::find_if(scenario.scene.objects, [&](const SceneObject& o) { return o.name == start_on; });
      const auto on_id = static_cast<std::int32_t>(on - scenario.scene.objects.begin());
      if (on != scenario.scene.objects.end() && !supports.contains(on_id)) {
        std::vector<std::string> under;
        for (const std::int32_t id : supports) under.push_back(scenario.scene.objects[id].name);
        problems.push_back(where + "on: '" + start_on + "', but the robot's feet at its start " +
                           FormatNumbers("(%.3f, %.3f) m ", scenario.robot->start_xyz_m.x(),
                                         scenario.robot->start_xyz_m.y()) +
                           (under.empty() ? std::string("stand on no object") : "stand on " + QuotedList(under)) +
                           "; place the start above '" + start_on + "' or leave `on` out");
      }
    }
  }

  // 2. the robot's surface inside an object other than its ground: the links
  // that reach into each object, one line per object
  for (const ObjectOverlap& overlap : Overlaps(scenario, world, robot)) {
    std::vector<std::string> links;
    for (const int link : overlap.links) links.push_back(model.link_name(link));
    problems.push_back(where + "the robot starts inside object '" + scenario.scene.objects[overlap.object_id].name +
                       "': link" + (links.size() == 1 ? " " : "s ") + QuotedList(links) +
                       (links.size() == 1 ? " reaches" : " reach") +
                       FormatNumbers(" into it (up to %.3f m deep, at (%.3f, %.3f, ", overlap.deepest_m,
                              overlap.p_W_deepest.x(), overlap.p_W_deepest.y()) +
                       FormatNumbers("%.3f) m); start the robot clear of it", overlap.p_W_deepest.z()) +
                       " (feet stand only on ground: to start standing on it, give `on: " +
                       scenario.scene.objects[overlap.object_id].name + "` in robot.start)");
  }
  locomotion.Reset();
  return problems;
}

}  // namespace proxsim
