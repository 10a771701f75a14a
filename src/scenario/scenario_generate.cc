// `scene: {generate: {...}}` (docs/worlds.md): the generator's keys read and
// checked, the world generated (scene/world_generator.h) and written into the
// scenario as plain objects (and the robot's path, when the scenario has a
// robot without one). A scenario with `generate` is read as the text this
// writes: `proxsim generate` writes that very text, so the generated run and
// the run of the written file read the same scenario.
#include "scenario/scenario_generate.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/input_error.h"
#include "core/text_fields.h"
#include "core/nearest_key.h"
#include "scenario/scenario_paths.h"
#include "scenario/yaml_reader.h"
#include "scene/world_generator.h"

namespace proxsim {

namespace {

// [easy, hard] of numbers obeying `rule`
void ReadRange(YamlReader& reader, const Field& field, const NumberRule& rule, GenRange* range) {
  if (!field) return;
  if (const auto values = reader.Numbers(field, 2, rule, "[easy, hard], two numbers")) *range = {(*values)[0], (*values)[1]};
}

// a family's map of ranges: {key: [easy, hard], ...}
void ReadFamily(YamlReader& reader, const Field& field, std::initializer_list<std::pair<const char*, GenRange*>> ranges) {
  if (!field) return;
  std::vector<const char*> keys;
  for (const auto& [key, range] : ranges) keys.push_back(key);
  // MapView takes an initializer list: open it with the keys one family at a time
  std::optional<MapView> map;
  if (keys.size() == 1) map = reader.Map(field, {keys[0]});
  if (keys.size() == 2) map = reader.Map(field, {keys[0], keys[1]});
  if (keys.size() == 3) map = reader.Map(field, {keys[0], keys[1], keys[2]});
  if (!map) return;
  for (const auto& [key, range] : ranges) ReadRange(reader, (*map)[key], AnyNumber(), range);
}

GenerateConfig ReadGenerate(YamlReader& reader, const Field& field) {
  GenerateConfig config;
  const auto map = reader.Map(field, {"kind", "seed", "difficulty",
                                      // course
                                      "length_m", "width_m", "elements", "stairs", "hole", "pit", "gap", "step", "boxes",
                                      "ramp", "flat_m",
                                      // room
                                      "size_m", "height_m", "robot_width_m", "margin_m", "tables", "chairs", "shelves",
                                      "clutter", "blockers", "people", "people_height_m", "people_speed_m_s"});
  if (!map) return config;
  const Field kind = (*map)["kind"];
  if (reader.Require(kind, "kind: course or room")) {
    if (const auto text = reader.String(kind)) {
      if (*text == "room") config.kind = GenerateConfig::Kind::kRoom;
      else if (*text != "course") reader.Fail(kind, "unknown kind '" + *text + "' (expected course or room)");
    }
  }
  config.seed = reader.Count((*map)["seed"]).value_or(config.seed);
  config.difficulty = reader.Number((*map)["difficulty"], NumberIn(0, 1)).value_or(config.difficulty);

  // the keys of the other kind are mistakes, not options
  const bool course = config.kind == GenerateConfig::Kind::kCourse;
  for (const char* key : {"length_m", "width_m", "elements", "stairs", "hole", "pit", "gap", "step", "boxes", "ramp", "flat_m"}) {
    if (!course && map->Has(key)) reader.Fail((*map)[key], std::string(key) + " is for kind: course");
  }
  for (const char* key : {"size_m", "height_m", "robot_width_m", "margin_m", "tables", "chairs", "shelves", "clutter",
                          "blockers", "people", "people_height_m", "people_speed_m_s"}) {
    if (course && map->Has(key)) reader.Fail((*map)[key], std::string(key) + " is for kind: room");
  }

  CourseConfig& c = config.course;
  c.length_m = reader.Number((*map)["length_m"], NumberIn(2, 1000, "m")).value_or(c.length_m);
  c.width_m = reader.Number((*map)["width_m"], NumberIn(0.5, 100, "m")).value_or(c.width_m);
  if (const auto items = !map->Has("elements") ? std::nullopt : reader.List((*map)["elements"], "a list of families (" + std::string("stairs_up, stairs_down, hole, pit, gap, step, boxes, ramp") + ")")) {
    const auto& names = CourseFamilyNames();
    for (const Field& item : *items) {
      const auto name = reader.String(item);
      if (!name) continue;
      const auto found = std::find(names.begin(), names.end(), *name);
      if (found != names.end()) {
        c.elements.push_back(static_cast<CourseFamily>(found - names.begin()));
        continue;
      }
      const auto nearest = NearestKey(*name, names);
      reader.Fail(item, "unknown family '" + *name + "' (" + (nearest ? "did you mean '" + *nearest + "'? " : "") +
                            "expected stairs_up, stairs_down, hole, pit, gap, step, boxes or ramp)");
    }
    if (items->empty()) reader.Fail((*map)["elements"], "expected at least one family");
  }
  ReadFamily(reader, (*map)["stairs"], {{"rise_m", &c.stairs_rise_m}, {"tread_m", &c.stairs_tread_m}, {"steps", &c.stairs_steps}});
  ReadFamily(reader, (*map)["hole"], {{"width_m", &c.hole_width_m}, {"depth_m", &c.hole_depth_m}});
  ReadFamily(reader, (*map)["pit"], {{"width_m", &c.pit_width_m}, {"depth_m", &c.pit_depth_m}});
  ReadFamily(reader, (*map)["gap"], {{"width_m", &c.gap_width_m}});
  ReadFamily(reader, (*map)["step"], {{"height_m", &c.step_height_m}});
  ReadFamily(reader, (*map)["boxes"], {{"height_m", &c.boxes_height_m}});
  ReadFamily(reader, (*map)["ramp"], {{"slope_deg", &c.ramp_slope_deg}});
  ReadRange(reader, (*map)["flat_m"], AnyNumber(), &c.flat_m);

  RoomConfig& r = config.room;
  if (const auto size = reader.Numbers((*map)["size_m"], 2, NumberIn(3, 100, "m"), "[x, y] in metres, each in [3, 100]"))
    r.size_m = Vec2((*size)[0], (*size)[1]);
  r.height_m = reader.Number((*map)["height_m"], PositiveNumber("m")).value_or(r.height_m);
  r.robot_width_m = reader.Number((*map)["robot_width_m"], PositiveNumber("m")).value_or(r.robot_width_m);
  r.margin_m = reader.Number((*map)["margin_m"], NonNegativeNumber("m")).value_or(r.margin_m);
  ReadRange(reader, (*map)["tables"], AnyNumber(), &r.tables);
  ReadRange(reader, (*map)["chairs"], AnyNumber(), &r.chairs);
  ReadRange(reader, (*map)["shelves"], AnyNumber(), &r.shelves);
  ReadRange(reader, (*map)["clutter"], AnyNumber(), &r.clutter);
  ReadFamily(reader, (*map)["blockers"],
             {{"count", &r.blockers}, {"width_m", &r.blocker_width_m}, {"height_m", &r.blocker_height_m}});
  ReadRange(reader, (*map)["people"], AnyNumber(), &r.people);
  ReadRange(reader, (*map)["people_height_m"], AnyNumber(), &r.person_height_m);
  ReadRange(reader, (*map)["people_speed_m_s"], AnyNumber(), &r.person_speed_m_s);

  // the ranges against each other and the room (a tread shorter than a foot, a person taller than the room)
  if (!reader.HasProblems()) {
    for (const std::string& problem : GenerateProblems(config)) reader.Fail(field, problem);
  }
  return config;
}

// a number as the generator rounded it: at most three decimals, no trailing zeros, no "-0"
std::string Number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", value);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

YAML::Node Numbers(std::initializer_list<double> values) {
  YAML::Node list(YAML::NodeType::Sequence);
  for (const double value : values) list.push_back(Number(value));
  list.SetStyle(YAML::EmitterStyle::Flow);
  return list;
}

YAML::Node ObjectNode(const GenObject& object) {
  YAML::Node node;
  node["name"] = object.name;
  switch (object.kind) {
    case GenObject::Kind::kBox: node["box"]["size_m"] = Numbers({object.size_m.x(), object.size_m.y(), object.size_m.z()}); break;
    case GenObject::Kind::kCylinder:
      node["cylinder"]["radius_m"] = Number(object.size_m.x());
      node["cylinder"]["length_m"] = Number(object.size_m.z());
      break;
    case GenObject::Kind::kSphere: node["sphere"]["radius_m"] = Number(object.size_m.x()); break;
    case GenObject::Kind::kPlane: node["plane"] = YAML::Node(YAML::NodeType::Map); break;
    case GenObject::Kind::kPerson: node["person"]["height_m"] = Number(object.size_m.z()); break;
  }
  if (object.kind != GenObject::Kind::kPlane && object.kind != GenObject::Kind::kPerson) {
    node["pose"]["xyz_m"] = Numbers({object.xyz_m.x(), object.xyz_m.y(), object.xyz_m.z()});
    if (!object.rpy_deg.isZero()) node["pose"]["rpy_deg"] = Numbers({object.rpy_deg.x(), object.rpy_deg.y(), object.rpy_deg.z()});
  }
  if (object.kind != GenObject::Kind::kPlane && object.kind != GenObject::Kind::kPerson)
    node["ground"] = object.ground;
  node["material"]["albedo"] = Number(object.albedo);
  if (!object.waypoints_m.empty()) {
    YAML::Node waypoints(YAML::NodeType::Sequence);
    for (const Vec2& p : object.waypoints_m) waypoints.push_back(Numbers({p.x(), p.y()}));
    waypoints.SetStyle(YAML::EmitterStyle::Flow);
    node["motion"]["waypoints_m"] = waypoints;
    node["motion"]["speed_m_s"] = Number(object.speed_m_s);
    node["motion"]["mode"] = "back_and_forth";
    node["motion"]["start_s"] = Number(object.start_s);
  }
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

}  // namespace

bool HasGenerate(const YAML::Node& document) {
  return document.IsMap() && document["scene"] && document["scene"].IsMap() && document["scene"]["generate"];
}

std::string GeneratedScenarioText(const std::string& yaml_text, const std::string& source,
                                  const std::string& written_to) {
  YamlReader reader(source);
  const YAML::Node document = GeneratedScenarioNode(reader.Parse(yaml_text), source);
  if (!written_to.empty()) {
    RebaseScenarioPaths(document, std::filesystem::path(source).parent_path(),
                        std::filesystem::path(written_to).parent_path());
  }
  YAML::Emitter out;
  out << document;
  return "# generated by proxsim from " + QuotedForComment(source) + "\n" + out.c_str() + "\n";
}

YAML::Node GeneratedScenarioNode(YAML::Node document, const std::string& source) {
  YamlReader reader(source);
  if (!HasGenerate(document)) {
    reader.FailFile("scene.generate: no world to generate (expected scene: {generate: {kind: course | room, ...}})");
    throw InputError(reader.Problems());
  }
  const Field scene_field{document["scene"], "scene", true};
  const auto scene = reader.Map(scene_field, {"builtin", "objects", "generate", "ambient_klux"});
  if (scene && scene->Has("builtin"))
    reader.Fail((*scene)["builtin"], "a generated world has no built-in scene; remove builtin or generate");
  const GenerateConfig config = ReadGenerate(reader, Field{document["scene"]["generate"], "scene.generate", true});
  if (reader.HasProblems()) throw InputError(reader.Problems());
  const GeneratedWorld world = GenerateWorld(config);

  // the scene: the generated objects, then the file's own
  YAML::Node objects(YAML::NodeType::Sequence);
  for (const GenObject& object : world.objects) objects.push_back(ObjectNode(object));
  if (const YAML::Node own = document["scene"]["objects"]; own && own.IsSequence()) {
    for (const YAML::Node& object : own) objects.push_back(object);
  }
  YAML::Node new_scene(YAML::NodeType::Map);
  new_scene["objects"] = objects;
  // (the scene's other keys are the file's own: read where any scene's are)
  if (const YAML::Node ambient = document["scene"]["ambient_klux"]; ambient) new_scene["ambient_klux"] = ambient;
  document["scene"] = new_scene;

  // the robot's path, unless the file gives its own
  if (YAML::Node robot = document["robot"]; robot && robot.IsMap() && !robot["path"] && !robot["trajectory"]) {
    YAML::Node waypoints(YAML::NodeType::Sequence);
    for (const Vec2& p : world.path_m) waypoints.push_back(Numbers({p.x(), p.y()}));
    waypoints.SetStyle(YAML::EmitterStyle::Flow);
    robot["path"]["waypoints_m"] = waypoints;
  }
  return document;
}

}  // namespace proxsim
