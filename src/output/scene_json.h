// scene.json: the geometry a run used (objects with shape, pose and material;
// the robot's links and their shapes; the sensors), so that the report can
// draw the scene, the robot and the true cross-section without re-parsing the
// scenario.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"
#include "raycast/ray_caster.h"
#include "sim/robot_in_scene.h"

namespace proxsim {

/// A shape and its pose as JSON fields: "shape", its dimensions, "xyz_m", "quat_wxyz".
nlohmann::json ShapeToJson(const Shape& shape, const Pose& X);


/// The whole scene.json document; `robot_links` empty when there is no robot.
nlohmann::json SceneToJson(const Scenario& scenario, const std::vector<LinkShapes>& robot_links);

/// scene.json's text: the document indented, except each mesh's vertex and
/// triangle lists, one line each (a robot of meshes would otherwise put a
/// million numbers on a million lines).
std::string SceneJsonText(const Scenario& scenario, const std::vector<LinkShapes>& robot_links);

}  // namespace proxsim
