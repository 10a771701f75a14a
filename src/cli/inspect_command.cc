// `proxsim inspect`: the robot loaded as a run loads it (robot/robot_inspect.h
// lists it, gait/leg_map_suggestion.h suggests its leg map), then printed as
// text or JSON. Nothing here computes geometry.
#include "inspect_command.h"

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "gait/leg_map_suggestion.h"
#include "robot/robot_inspect.h"
#include "scenario/scenario.h"
#include "sim/make_locomotion.h"

namespace proxsim {

namespace {

// The robot a target names: builtin:NAME, a scenario's robot, or a URDF.
RobotModel LoadTarget(const std::string& target) {
  RobotConfig config;
  if (target.ends_with(".yaml") || target.ends_with(".yml")) {
    const Scenario scenario = LoadScenarioFile(target);
    if (!scenario.robot) throw InputError(target + ": robot: the scenario has no robot to inspect");
    config = *scenario.robot;
  } else {
    config.model = target;
  }
  return LoadRobotModel(config);
}

nlohmann::json VecJson(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json BoxJson(const std::optional<BoundingBox>& box) {
  if (!box) return nullptr;
  return {{"min", VecJson(box->min_m)}, {"max", VecJson(box->max_m)}};
}

// each keyframe's moving joints by name (rad or m), and the root's height when the key places it
nlohmann::json KeyframesJson(const RobotModel& model) {
  nlohmann::json keys = nlohmann::json::array();
  for (const RobotKeyframe& key : model.keyframes()) {
    nlohmann::json q = nlohmann::json::object();
    for (const int j : model.MovingJoints()) q[model.joint_name(j)] = key.q_by_joint[j];
    keys.push_back({{"name", key.name},
                    {"root_z_m", key.has_root ? nlohmann::json(key.X_WRoot.translation().z()) : nlohmann::json(nullptr)},
                    {"q", q}});
  }
  return keys;
}

// the world body's geoms of an MJCF scene file: what a scenario takes as scene objects
nlohmann::json ModelSceneJson(const RobotModel& model) {
  nlohmann::json geoms = nlohmann::json::array();
  for (const ModelSceneGeom& geom : model.scene_geoms()) {
    nlohmann::json objects = nlohmann::json::array();
    for (const SceneObject& object : geom.objects) {
      objects.push_back({{"name", object.name},
                         {"shape", ShapeKindName(object.shape)},
                         {"xyz_m", VecJson(object.X_WO.translation())},
                         {"rpy_deg", VecJson(RpyFromRotation(object.X_WO.linear()) * (180.0 / kPi))},
                         {"ground", object.ground}});
    }
    geoms.push_back({{"geom", geom.geom},
                     {"type", geom.type},
                     {"group", geom.group},
                     {"ground_plane", geom.ground_plane},
                     {"objects", objects},
                     {"problem", geom.problem.empty() ? nlohmann::json(nullptr) : nlohmann::json(geom.problem)}});
  }
  return geoms;
}

nlohmann::json InspectJson(const RobotModel& model, const RobotSummary& summary, const LegMapSuggestion& legs) {
  nlohmann::json json = {{"proxsim_inspect", 1},
                         {"robot", {{"name", model.name()},
                                    {"source", model.source()},
                                    {"root_link", model.link_name(model.root_link())},
                                    {"mass_kg", model.TotalMass_kg()},
                                    {"mesh_files", model.MeshFileCount()},
                                    {"mesh_triangles", model.MeshTriangleCount()},
                                    {"loader", model.loader().empty() ? nlohmann::json(nullptr) : nlohmann::json(model.loader())}}},
                         {"keyframes", KeyframesJson(model)},
                         {"links", nlohmann::json::array()},
                         {"joints", nlohmann::json::array()},
                         {"feet_candidates", nlohmann::json::array()}};
  for (const LinkSummary& link : summary.links) {
    const RobotLink& l = model.link(link.link);
    json["links"].push_back({{"name", l.name},
                             {"depth", link.depth},
                             {"parent_joint", link.parent_joint.empty() ? nlohmann::json(nullptr) : nlohmann::json(link.parent_joint)},
                             {"geometry", link.shapes},
                             {"geometry_kind", link.shapes.empty() ? nlohmann::json(nullptr)
                                                                   : nlohmann::json(LinkGeometryKindName(l.shapes_kind))},
                             {"box_link_m", BoxJson(link.box_L)},
                             {"box_world_m", BoxJson(link.box_W)},
                             {"mass_kg", link.mass_kg}});
  }
  for (const int j : summary.joints) {
    const RobotJoint& joint = model.joint(j);
    nlohmann::json limits = nullptr;
    if (joint.has_limits) {
      limits = {{"lower", joint.lower}, {"upper", joint.upper}, {"velocity", joint.velocity}, {"effort", joint.effort}};
    }
    json["joints"].push_back({{"name", joint.name},
                              {"type", JointTypeName(joint.type)},
                              {"parent", model.link_name(joint.parent_link)},
                              {"child", model.link_name(joint.child_link)},
                              {"axis", VecJson(joint.axis_J)},
                              {"axis_world", VecJson(summary.X_WJ[j].linear() * joint.axis_J)},
                              {"origin_world_m", VecJson(summary.X_WJ[j].translation())},
                              {"limits", limits}});
  }
  for (const FootCandidate& foot : legs.feet) {
    json["feet_candidates"].push_back(
        {{"link", model.link_name(foot.link)}, {"lowest_z_m", foot.lowest_z_m}, {"y_m", foot.y_m}});
  }
  nlohmann::json map = nlohmann::json::object(), shanks = nlohmann::json::object(), why = nlohmann::json::array();
  for (int s = 0; s < 2; ++s) {
    const char* side = s == 0 ? "left" : "right";
    const LegSuggestion& leg = legs.legs[s];
    if (leg.names) {
      map[side] = {{"hip", leg.names->hip}, {"knee", leg.names->knee}, {"ankle", leg.names->ankle},
                   {"foot", leg.names->foot}};
      // the foot's pitch at joint zero the gait found (it walks the sole flat)
      if (legs.accepted) map[side]["ankle_zero_deg"] = legs.ankle_zero_deg[s];
    } else {
      map[side] = nullptr;
      why.push_back(std::string(side) + ": " + leg.problem);
    }
    if (leg.shank_link < 0) {
      shanks[side] = nullptr;
      continue;
    }
    nlohmann::json front = nlohmann::json::array();
    for (const ShankSpot& spot : leg.shank_front) {
      front.push_back({{"fraction", spot.fraction}, {"xyz_m", VecJson(spot.p_L)}, {"rpy_deg", VecJson(spot.rpy_deg)},
                       {"rpy_deg_pitched_down", VecJson(spot.rpy_deg_pitched_down)},
                       {"pitched_down_deg", kShankPitchDown_deg}, {"stand_off_m", kShankStandOff_m}});
    }
    shanks[side] = {{"link", model.link_name(leg.shank_link)}, {"front_surface", front}};
  }
  for (const std::string& problem : legs.problems) why.push_back(problem);
  json["legs"] = map;
  json["model_scene"] = ModelSceneJson(model);
  json["legs_accepted"] = legs.accepted;
  json["legs_problems"] = why;
  json["shanks"] = shanks;
  return json;
}

std::string Vec(const Vec3& v) {
  char text[96];
  // (+ 0.0 turns a negative zero into 0: "-0.0000" only puzzles a reader)
  std::snprintf(text, sizeof text, "[%.4f, %.4f, %.4f]", v.x() + 0.0, v.y() + 0.0, v.z() + 0.0);
  return text;
}

// an MJCF scene file: the robot is the world body's one tree, its other geoms the scene offered
void PrintModelScene(const RobotModel& model) {
  if (model.scene_geoms().empty()) return;
  std::printf("the robot is the tree under the world body from '%s'; the world body's %zu geom(s) are a scene, not "
              "the robot: a scenario takes them as scene objects (robot.model_scene: include, the default), the "
              "ground plane only when its scene has no ground of its own:\n",
              model.link_name(model.root_link()).c_str(), model.scene_geoms().size());
  for (const ModelSceneGeom& geom : model.scene_geoms()) {
    std::printf("  %s (%s, group %d): ", geom.geom.c_str(), geom.type.c_str(), geom.group);
    if (!geom.problem.empty()) {
      std::printf("not taken: %s\n", geom.problem.c_str());
      continue;
    }
    if (geom.ground_plane) std::printf("the ground (z = 0, facing up), ");
    for (std::size_t i = 0; i < geom.objects.size(); ++i) {
      const SceneObject& object = geom.objects[i];
      std::printf("%sscene object '%s', a %s at %s m", i == 0 ? "" : "; ", object.name.c_str(), ShapeKindName(object.shape),
                  Vec(object.X_WO.translation()).c_str());
    }
    std::printf("\n");
  }
}

void PrintText(const RobotModel& model, const RobotSummary& summary, const LegMapSuggestion& legs) {
  std::printf("robot '%s' (%s): %d links, %d joints, %.2f kg, %zu mesh files\n", model.name().c_str(),
              model.source().c_str(), model.link_count(), model.joint_count(), model.TotalMass_kg(),
              model.MeshFileCount());
  if (!model.loader().empty()) std::printf("read through %s (what it compiled)\n", model.loader().c_str());
  std::printf("reference pose: every joint at 0, the root link '%s' at the world origin (x forward, y left, z up)\n",
              model.link_name(model.root_link()).c_str());
  PrintModelScene(model);
  for (const RobotKeyframe& key : model.keyframes()) {
    std::printf("keyframe '%s'", key.name.c_str());
    if (key.has_root) std::printf(": root at z %.4f m", key.X_WRoot.translation().z());
    int shown = 0;
    for (const int j : model.MovingJoints()) {
      if (key.q_by_joint[j] == 0.0) continue;
      std::printf("%s%s %.4g", shown++ == 0 ? "; joints not at 0: " : ", ", model.joint_name(j).c_str(), key.q_by_joint[j]);
    }
    std::printf("\n");
  }
  std::printf("\n");

  std::printf("links, in tree order (bounding boxes [min] .. [max] in metres):\n");
  for (const LinkSummary& link : summary.links) {
    const std::string indent(2 + 2 * link.depth, ' ');
    std::string shapes;
    for (const std::string& shape : link.shapes) shapes += (shapes.empty() ? "" : ", ") + shape;
    std::printf("%s%s  (%s)  %.3f kg%s%s\n", indent.c_str(), model.link_name(link.link).c_str(),
                shapes.empty() ? "no geometry" : shapes.c_str(), link.mass_kg,
                link.parent_joint.empty() ? "" : ", joint ", link.parent_joint.c_str());
    if (link.box_L) {
      std::printf("%s  in its frame %s .. %s\n", indent.c_str(), Vec(link.box_L->min_m).c_str(),
                  Vec(link.box_L->max_m).c_str());
      std::printf("%s  in the world %s .. %s\n", indent.c_str(), Vec(link.box_W->min_m).c_str(),
                  Vec(link.box_W->max_m).c_str());
    }
  }

  std::printf("\njoints, in tree order (limits: rad or m, rad/s or m/s, N·m or N):\n");
  for (const int j : summary.joints) {
    const RobotJoint& joint = model.joint(j);
    std::printf("  %-28s %-10s %s -> %s", joint.name.c_str(), JointTypeName(joint.type),
                model.link_name(joint.parent_link).c_str(), model.link_name(joint.child_link).c_str());
    if (joint.type != JointType::kFixed) {
      std::printf(", axis %s (world %s)", Vec(joint.axis_J).c_str(), Vec(summary.X_WJ[j].linear() * joint.axis_J).c_str());
    }
    if (joint.has_limits) {
      std::printf(", lower %g upper %g velocity %g effort %g", joint.lower, joint.upper, joint.velocity, joint.effort);
    }
    std::printf("\n");
  }

  std::printf("\nfeet candidates (the lowest link of each chain reaching the ground):\n");
  if (legs.feet.empty()) std::printf("  none\n");
  for (const FootCandidate& foot : legs.feet) {
    std::printf("  %-28s lowest z %.4f m, centre y %.4f m (%s)\n", model.link_name(foot.link).c_str(), foot.lowest_z_m,
                foot.y_m, foot.y_m > 0 ? "left" : "right");
  }

  std::printf("\nsuggested leg map (pitch joints found by axis along y and height, not by name):\n");
  if (legs.legs[0].names && legs.legs[1].names) {
    std::printf("robot:\n  legs:\n");
    for (int s = 0; s < 2; ++s) {
      const LegNames& n = *legs.legs[s].names;
      // a foot pitched at joint zero: the pitch the gait found, written as the key that would give it
      char ankle_zero[64] = "";
      if (legs.accepted && legs.ankle_zero_deg[s] != 0.0)
        std::snprintf(ankle_zero, sizeof ankle_zero, ", ankle_zero_deg: %.1f", legs.ankle_zero_deg[s]);
      std::printf("    %-6s {hip: %s, knee: %s, ankle: %s, foot: %s%s}\n", s == 0 ? "left:" : "right:", n.hip.c_str(),
                  n.knee.c_str(), n.ankle.c_str(), n.foot.c_str(), ankle_zero);
    }
    if (legs.accepted && (legs.ankle_zero_deg[0] != 0.0 || legs.ankle_zero_deg[1] != 0.0))
      std::printf("  (a foot not flat at joint zero: the gait found the pitch its sole lies flattest at, toe up "
                  "positive, and walks it flat; give ankle_zero_deg to set it)\n");
    std::printf("%s\n", legs.accepted ? "  (read as the gait reads robot.legs: accepted)"
                                      : "  (the gait's leg reader refuses it:)");
  }
  for (int s = 0; s < 2; ++s)
    if (!legs.legs[s].names) std::printf("  %s: %s\n", s == 0 ? "left" : "right", legs.legs[s].problem.c_str());
  for (const std::string& problem : legs.problems) std::printf("  %s\n", problem.c_str());

  std::printf("\nshank front surfaces (a sensor's origin %g mm proud of the shank's front, in its link frame; +x of rpy_deg "
              "is forward, level or pitched down %g deg):\n",
              1000 * kShankStandOff_m, kShankPitchDown_deg);
  for (int s = 0; s < 2; ++s) {
    const LegSuggestion& leg = legs.legs[s];
    if (leg.shank_link < 0) continue;
    std::printf("  %s\n", model.link_name(leg.shank_link).c_str());
    if (leg.shank_front.empty()) std::printf("    the line from the knee forward meets no geometry\n");
    for (const ShankSpot& spot : leg.shank_front) {
      std::printf("    %3.0f %% of the way knee -> ankle: xyz_m %s, rpy_deg %s (level) or %s (pitched down)\n",
                  100 * spot.fraction, Vec(spot.p_L).c_str(), Vec(spot.rpy_deg).c_str(),
                  Vec(spot.rpy_deg_pitched_down).c_str());
    }
  }
}

}  // namespace

int InspectCommand(const std::string& target, bool json) {
  const RobotModel model = LoadTarget(target);
  const RobotSummary summary = SummarizeRobot(model);
  const LegMapSuggestion legs = SuggestLegMap(model, summary);
  if (json) {
    std::printf("%s\n", InspectJson(model, summary, legs).dump(2).c_str());
  } else {
    PrintText(model, summary, legs);
  }
  return 0;
}

}  // namespace proxsim
