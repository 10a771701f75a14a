// The `scene` section: a built-in scene (scene/scene.h) plus the file's own
// objects. Each object has a name, exactly one shape key, an optional pose,
// an optional material, an optional `ground` flag (the feet stand on it) and
// an optional motion (scenario_motion.cc); a `person` is its parts (scene/person.h).
// Meshes are loaded here, through Assimp, so that a missing or broken mesh
// file is reported with the other problems before anything runs.
#include <map>

#include "core/input_error.h"
#include "core/nearest_key.h"
#include "core/text_fields.h"
#include "scenario/param_reader.h"
#include "scenario/scenario_sections.h"
#include "scene/mesh_loader.h"
#include "scene/person.h"

namespace proxsim {

namespace {

constexpr const char* kShapeKeys[] = {"box", "sphere", "cylinder", "plane", "mesh", "person"};

std::string JoinNames(const std::vector<std::string>& names) {
  std::string all;
  for (const auto& name : names) all += (all.empty() ? "" : ", ") + name;
  return all;
}

// box: {size_m: [x, y, z]} — full extents
Box ReadBox(YamlReader& reader, const Field& field) {
  Box box;
  const auto map = reader.Map(field, {"size_m"});
  if (!map) return box;
  const Field size = (*map)["size_m"];
  if (reader.Require(size, "size_m: [x, y, z], the full extents in metres")) {
    if (auto size_m = reader.Vector3(size, PositiveLength(), "[x, y, z], the full extents in metres")) {
      box.size_m = *size_m;
    }
  }
  return box;
}

// sphere: {radius_m}
Sphere ReadSphere(YamlReader& reader, const Field& field) {
  Sphere sphere;
  const auto map = reader.Map(field, {"radius_m"});
  if (!map) return sphere;
  const Field radius = (*map)["radius_m"];
  if (reader.Require(radius, "radius_m, a finite number > 0 m")) {
    sphere.radius_m = reader.Number(radius, PositiveLength()).value_or(sphere.radius_m);
  }
  return sphere;
}

// cylinder: {radius_m, length_m} — axis along the object's z
Cylinder ReadCylinder(YamlReader& reader, const Field& field) {
  Cylinder cylinder;
  const auto map = reader.Map(field, {"radius_m", "length_m"});
  if (!map) return cylinder;
  const Field radius = (*map)["radius_m"];
  const Field length = (*map)["length_m"];
  if (reader.Require(radius, "radius_m, a finite number > 0 m")) {
    cylinder.radius_m = reader.Number(radius, PositiveLength()).value_or(cylinder.radius_m);
  }
  if (reader.Require(length, "length_m, a finite number > 0 m")) {
    cylinder.length_m = reader.Number(length, PositiveLength()).value_or(cylinder.length_m);
  }
  return cylinder;
}

// mesh: {file, scale} — scale is one number or [x, y, z]; the file is loaded now
Mesh ReadMesh(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir) {
  Mesh mesh;
  const auto map = reader.Map(field, {"file", "scale"});
  if (!map) return mesh;

  // scale: a uniform factor or one per axis
  const Field scale = (*map)["scale"];
  if (scale && scale.node.IsSequence()) {
    const auto factors = reader.Vector3(scale, PositiveNumber(), "a number > 0 or [x, y, z] of numbers > 0");
    if (factors) mesh.scale = *factors;
  } else if (scale) {
    NumberRule rule = PositiveNumber();
    rule.expected = "a number > 0 or [x, y, z] of numbers > 0";
    const auto factor = reader.Number(scale, rule);
    if (factor) mesh.scale = Vec3::Constant(*factor);
  }

  // file: relative to the scenario's folder
  const Field file = (*map)["file"];
  if (!reader.Require(file, "file, the path of a mesh file (OBJ, STL, PLY, glTF, ...)")) return mesh;
  const auto text = reader.String(file);
  if (!text) return mesh;
  mesh.file = *text;
  try {
    // loaded even with a bad scale (then unscaled), so that a bad file is reported too
    mesh.data = LoadMeshFile(ResolveScenarioPath(base_dir, *text).string(), mesh.scale);
  } catch (const InputError& error) {
    for (const auto& problem : error.problems()) reader.Fail(file, problem);
  }
  return mesh;
}

// material: by its declaration (MaterialSchema(), scene/scene.h)
Material ReadMaterial(YamlReader& reader, const Field& field) {
  Material material;
  const auto map = OpenSection(reader, field, MaterialSchema());
  if (!map) return material;
  ReadParams(reader, *map, MaterialSchema(), material);
  ReportAtKeys(reader, *map, CheckParamBounds(MaterialSchema(), material));
  return material;
}

// ground: true/false, whether the feet stand on the object. Absent, a plane
// is ground (a scenario's plane is its floor) and any other shape is not.
bool ReadGround(YamlReader& reader, const Field& field, const std::optional<Shape>& shape) {
  const bool is_plane = shape && std::holds_alternative<Plane>(*shape);
  return reader.Bool(field).value_or(is_plane);
}

// The one shape of an object, or nullopt after reporting none or several
// (and for a person, whose parts the caller makes).
std::optional<Shape> ReadShape(YamlReader& reader, const MapView& object, const std::filesystem::path& base_dir) {
  std::vector<std::string> given;
  for (const char* key : kShapeKeys) {
    if (object.Has(key)) given.emplace_back(key);
  }
  if (given.size() != 1) {
    reader.Fail(object.field(), "expected exactly one shape key (box, sphere, cylinder, plane, mesh or person), got " +
                                    (given.empty() ? std::string("none") : JoinNames(given)));
    return std::nullopt;
  }
  const std::string& kind = given.front();
  const Field field = object[kind];
  if (kind == "box") return ReadBox(reader, field);
  if (kind == "sphere") return ReadSphere(reader, field);
  if (kind == "cylinder") return ReadCylinder(reader, field);
  if (kind == "mesh") return ReadMesh(reader, field, base_dir);
  if (kind == "person") return std::nullopt;  // not one shape: parts, read by the caller
  reader.Map(field, {});  // a plane takes no parameters
  return Plane{};
}

}  // namespace

void ReadScene(YamlReader& reader, const Field& field, const std::filesystem::path& base_dir, Scenario& scenario) {
  const auto scene = reader.Map(field, {"builtin", "objects", "ambient_klux"});
  if (!scene) return;
  // the light the time-of-flight parts' range tables read (ST's conditions: 0 indoor, 5 outdoor overcast)
  const Field ambient = (*scene)["ambient_klux"];
  double ambient_klux = 0.0;
  if (const auto klux = reader.Number(ambient)) {
    if (*klux >= 0) {
      ambient_klux = *klux;
    } else {
      reader.Fail(ambient, "expected an ambient light >= 0 klux (0: ST's indoor, no infrared; 5: ST's outdoor "
                           "overcast, VL53L0X datasheet DocID029104 Table 11), got " + DescribeNode(ambient.node));
    }
  }

  // the built-in scene, by name
  const Field builtin = (*scene)["builtin"];
  if (const auto name = reader.String(builtin)) {
    const auto& names = BuiltinSceneNames();
    if (std::find(names.begin(), names.end(), *name) != names.end()) {
      scenario.builtin_scene = *name;
    } else {
      const auto nearest = NearestKey(*name, names);
      reader.Fail(builtin, "unknown built-in scene '" + *name + "' (" +
                               (nearest ? "did you mean '" + *nearest + "'? " : "") + "expected one of " +
                               JoinNames(names) + ")");
    }
  }
  try {
    scenario.scene = MakeBuiltinScene(scenario.builtin_scene);
  } catch (const InputError& error) {
    for (const auto& problem : error.problems()) reader.Fail(builtin, problem);
  }

  // where each name comes from, for duplicate reports
  std::map<std::string, std::string> name_origin;
  for (const auto& object : scenario.scene.objects) {
    name_origin.emplace(object.name, "the built-in scene '" + scenario.builtin_scene + "'");
  }

  // the file's own objects
  const auto items = reader.List((*scene)["objects"], "a list of objects");
  if (!items) return;
  for (const Field& item : *items) {
    const auto object =
        reader.Map(item, {"name", "box", "sphere", "cylinder", "plane", "mesh", "person", "pose", "material", "ground", "motion"},
                   "a map with a name and one shape (box, sphere, cylinder, plane, mesh or person)");
    if (!object) continue;
    SceneObject scene_object;
    const Field name = (*object)["name"];
    if (reader.Require(name, "name, unique in the scene")) {
      if (const auto text = reader.String(name)) {
        scene_object.name = *text;
        // printable UTF-8 only: the JSON outputs stay valid (commas are quoted in CSV)
        if (const std::string problem = NamingProblem(*text); !problem.empty())
          reader.Fail(name, "expected a name of printable UTF-8 text, got " + problem);
        const auto [previous, inserted] = name_origin.emplace(*text, item.path);
        if (!inserted) reader.Fail(name, "duplicate object name '" + *text + "' (already used by " + previous->second + ")");
      }
    }
    const auto shape = ReadShape(reader, *object, base_dir);
    // a moving object's pose is in its motion's frame (scene/motion.h)
    const Pose pose = ReadPose(reader, (*object)["pose"]);
    scene_object.motion = ReadMotion(reader, (*object)["motion"], base_dir);
    scene_object.material = ReadMaterial(reader, (*object)["material"]);
    const Field ground = (*object)["ground"];
    if (scene_object.motion || object->Has("person")) {
      // a moving object (or a person) is never stood on: the feet need ground that stays put
      if (reader.Bool(ground).value_or(false))
        reader.Fail(ground, std::string("a ") + (scene_object.motion ? "moving object" : "person") +
                                " cannot be ground (the feet land only on what stays put); expected false or no key");
    } else {
      scene_object.ground = ReadGround(reader, ground, shape);
    }
    if (object->Has("person")) {
      // a person is its parts, each an object of its own (NAME/left_leg, ...)
      const double height_m = ReadPersonHeight(reader, (*object)["person"]);
      for (SceneObject& part : PersonParts(scene_object.name, height_m, pose, scene_object.material, scene_object.motion)) {
        name_origin.emplace(part.name, item.path);
        scenario.scene.objects.push_back(std::move(part));
      }
      continue;
    }
    if (!shape) continue;
    scene_object.shape = *shape;
    if (scene_object.motion) {
      scene_object.motion->X_MO = pose;
      scene_object.X_WO = MotionPoseAt(*scene_object.motion, 0.0);
    } else {
      scene_object.X_WO = pose;
    }
    scenario.scene.objects.push_back(std::move(scene_object));
  }
  scenario.scene.ambient_klux = ambient_klux;  // after the built-in scene, which starts from its defaults
}

}  // namespace proxsim
