// A scene: named objects with a shape, a pose in the world and a material.
// The objects of a built-in scene come first, then the scenario's own.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/config_schema.h"
#include "scene/motion.h"
#include "scene/shape.h"

namespace proxsim {

/// Surface properties. Stored for every object; the paper's sensor models do
/// not use them; a sensor that opts in does (docs/sensors.md, "Beyond the paper").
struct Material {
  constexpr Material() = default;
  constexpr Material(double albedo_in, double specular_in) : albedo(albedo_in), specular(specular_in) {}

  double albedo = 1.0;    ///< diffuse reflectance in [0, 1]
  double specular = 0.0;  ///< specular fraction of the reflection in [0, 1]
  std::optional<double> ir_albedo;              ///< in [0, 1]; the infrared sensors' albedo when not `albedo`
  std::optional<double> acoustic_reflectivity;  ///< in [0, 1]; fraction of sound returned; absent: 1
};

/// An object's `material:` keys declared once (core/config_schema.h): the
/// scenario reader, docs/scenario.md's table and the writer follow them.
const ConfigSchema<Material>& MaterialSchema();

struct SceneObject {
  std::string name;  ///< unique within the scene; the `object` column of readings.csv
  Shape shape;
  /// Pose of the object's frame O in world W; for a moving object, at t = 0
  /// (where it is at time t: MotionPoseAt(*motion, t)).
  Pose X_WO = Pose::Identity();
  Material material;
  /// The ground the feet stand on: the robot's clearance leaves it out, and a
  /// study counts it as floor seen. A role declared here (scenario key
  /// `ground`), never read from the name.
  bool ground = false;
  /// How it moves (scene/motion.h); absent: it stands still. A moving object is never ground.
  std::optional<Motion> motion = std::nullopt;
};

struct Scene {
  std::vector<SceneObject> objects;
  /// The ambient light at 940 nm as an illuminance equivalent, klux, >= 0: 0 is
  /// indoor without infrared (ST's "indoor" condition), 5 ST's "outdoor
  /// overcast" (docs/sensors.md). Time-of-flight parts with a range table read it.
  double ambient_klux = 0.0;
};

/// Names of the built-in scenes, for validation and messages.
const std::vector<std::string>& BuiltinSceneNames();

/// The objects of a built-in scene; throws InputError for an unknown name.
Scene MakeBuiltinScene(const std::string& name);

}  // namespace proxsim
