#include "study/study_config.h"
#include "core/message_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "scenario/scenario_sections.h"
#include "scenario/yaml_reader.h"
#include "scene/scene.h"

namespace proxsim {

namespace {

// {from, to, step}: from, from + step, ... up to `to` included (step default 1)
std::vector<double> NumberRange(YamlReader& reader, const Field& field) {
  std::vector<double> values;
  const auto range = reader.Map(field, {"from", "to", "step"}, "a range {from, to, step}");
  if (!range) return values;
  const auto from = reader.Number((*range)["from"]);
  const auto to = reader.Number((*range)["to"]);
  const auto step = (*range)["step"] ? reader.Number((*range)["step"]) : std::optional<double>(1.0);
  if (!(*range)["from"] || !(*range)["to"]) reader.Fail(field, "expected both from and to");
  if (!from || !to || !step) return values;
  if (*step <= 0) {
    reader.Fail((*range)["step"], "expected a step > 0");
    return values;
  }
  if (*from > *to) {
    reader.Fail(field, "empty range: from " + std::to_string(*from) + " is beyond to " + std::to_string(*to));
    return values;
  }
  // by multiplication, not accumulation: the last value lands on `to` when the step divides the span
  const auto count = static_cast<std::size_t>(std::floor((*to - *from) / *step + 1e-9)) + 1;
  if (count > 100000) {
    reader.Fail(field, "a range of " + std::to_string(count) + " values: expected at most 100000");
    return values;
  }
  for (std::size_t i = 0; i < count; ++i) values.push_back(*from + static_cast<double>(i) * *step);
  return values;
}

// a list of numbers, a range, or one number standing for a list of one
std::vector<double> NumberAxis(YamlReader& reader, const Field& field, std::vector<double> otherwise) {
  if (!field) return otherwise;
  if (field.node.IsScalar()) {
    const auto value = reader.Number(field);
    return value ? std::vector<double>{*value} : std::vector<double>{};
  }
  if (field.node.IsMap()) return NumberRange(reader, field);
  std::vector<double> values;
  const auto items = reader.List(field, "a number, a list of numbers or a range {from, to, step}");
  if (!items) return values;
  if (items->empty()) reader.Fail(field, "expected at least one value, got an empty list");
  for (const Field& item : *items) {
    if (const auto value = reader.Number(item)) values.push_back(*value);
  }
  return values;
}

std::vector<std::string> TextAxis(YamlReader& reader, const Field& field, const std::string& what) {
  std::vector<std::string> values;
  if (!field) {
    reader.Fail(field, "expected " + what);
    return values;
  }
  if (field.node.IsScalar()) {
    if (const auto value = reader.String(field)) values.push_back(*value);
    return values;
  }
  const auto items = reader.List(field, what);
  if (!items) return values;
  if (items->empty()) reader.Fail(field, "expected at least one value, got an empty list");
  for (const Field& item : *items) {
    if (const auto value = reader.String(item)) values.push_back(*value);
  }
  return values;
}


// a candidate of the base's presets for a type name (a sensor type or a real part)
std::optional<SensorSpec> SpecOf(const std::string& type) {
  if (const auto sensor_type = SensorTypeFromName(type)) return SensorSpec::Preset(*sensor_type);
  return SensorSpec::PartPreset(type);
}

Candidate MakeCandidate(const SensorSpec& spec, const std::string& type, const std::string& link, double along_m,
                        double forward_m, double pitch_deg, double yaw_deg) {
  Candidate c;
  c.type = type;
  c.id = type + "@" + link + ":z" + FormatNumbers("%+.3g", along_m) + ":x" + FormatNumbers("%.3g", forward_m) + ":p" +
         FormatNumbers("%.3g", pitch_deg) + ":y" + FormatNumbers("%.3g", yaw_deg);
  c.sensor.name = c.id;
  c.sensor.spec = spec;
  // a part samples at its datasheet's limit, as in a scenario (sensors/sensor_spec.h PartRateLimit)
  c.sensor.rate_hz = PartRateLimit(spec).max_hz;
  c.sensor.link = link;
  c.sensor.X_LS = PoseFromXyzRpy(Vec3(forward_m, 0, along_m), Vec3(0, DegToRad(pitch_deg), DegToRad(yaw_deg)));
  c.along_m = along_m;
  c.forward_m = forward_m;
  c.pitch_deg = pitch_deg;
  c.yaw_deg = yaw_deg;
  c.xyz_m = Vec3(forward_m, 0, along_m);
  c.rpy_deg = Vec3(0, pitch_deg, yaw_deg);
  return c;
}

// (the links are checked when each variant's world is built, before any run)
void ReadCandidates(YamlReader& reader, const Field& field, StudyConfig& study, bool allow_large) {
  const auto map = reader.Map(field, {"axes", "list"});
  if (!map) return;
  if (!(*map)["axes"] && !(*map)["list"]) reader.Fail(field, "expected axes, a list, or both: no candidate to study");
  const auto axes = (*map)["axes"] ? reader.Map((*map)["axes"], {"type", "link", "along_m", "forward_m", "pitch_deg",
                                                                  "yaw_deg"})
                                    : std::nullopt;
  if (axes) {
    const auto types = TextAxis(reader, (*axes)["type"], "a sensor type or part, or a list of them");
    const auto links = TextAxis(reader, (*axes)["link"], "a robot link, or a list of them");
    const auto along = NumberAxis(reader, (*axes)["along_m"], {0.0});
    const auto forward = NumberAxis(reader, (*axes)["forward_m"], {0.0});
    const auto pitch = NumberAxis(reader, (*axes)["pitch_deg"], {0.0});
    const auto yaw = NumberAxis(reader, (*axes)["yaw_deg"], {0.0});
    // the product is counted before any candidate is made (in double: it may overflow)
    const double product = static_cast<double>(types.size()) * links.size() * along.size() * forward.size() *
                           pitch.size() * yaw.size();
    const std::size_t limit = allow_large ? kHardMaxStudyCandidates : kMaxStudyCandidates;
    if (product > static_cast<double>(limit)) {
      char count[32];
      std::snprintf(count, sizeof count, "%.4g", product);
      reader.Fail((*map)["axes"], std::string("the axes make ") + count + " candidates (" +
                                      std::to_string(types.size()) + " types x " + std::to_string(links.size()) +
                                      " links x " + std::to_string(along.size()) + " x " +
                                      std::to_string(forward.size()) + " x " + std::to_string(pitch.size()) + " x " +
                                      std::to_string(yaw.size()) + " positions and angles); expected at most " +
                                      std::to_string(limit) +
                                      (allow_large ? " even with --allow-large"
                                                   : " (each is a sensor in every job's simulation); narrow the "
                                                     "axes, or pass --allow-large"));
      return;
    }
    for (const std::string& type : types) {
      const auto spec = SpecOf(type);
      if (!spec) {
        reader.Fail((*axes)["type"], "unknown sensor type or part '" + type +
                                         "'; expected ideal, laser, ultrasonic, reflectance or a part name");
        continue;
      }
      for (const std::string& link : links) {
        for (double a : along)
          for (double f : forward)
            for (double p : pitch)
              for (double y : yaw) study.candidates.push_back(MakeCandidate(*spec, type, link, a, f, p, y));
      }
    }
  }
  if (const Field list = (*map)["list"]) {
    const auto items = reader.List(list, "a list of {type, link, xyz_m, rpy_deg}");
    for (const Field& item : items.value_or(std::vector<Field>{})) {
      const auto one = reader.Map(item, {"type", "link", "xyz_m", "rpy_deg"});
      if (!one) continue;
      const auto type = reader.String((*one)["type"]);
      const auto link = reader.String((*one)["link"]);
      const auto xyz = reader.Vector3((*one)["xyz_m"], AnyNumber(), "[x, y, z] in metres").value_or(Vec3::Zero());
      const auto rpy = reader.Vector3((*one)["rpy_deg"], AnyNumber(), "[roll, pitch, yaw] in degrees").value_or(Vec3::Zero());
      if (!type || !link) {
        if (!type) reader.Fail(item, "expected a type");
        if (!link) reader.Fail(item, "expected a link");
        continue;
      }
      const auto spec = SpecOf(*type);
      if (!spec) {
        reader.Fail((*one)["type"], "unknown sensor type or part '" + *type + "'");
        continue;
      }
      Candidate c = MakeCandidate(*spec, *type, *link, xyz.z(), xyz.x(), rpy.y(), rpy.z());
      c.sensor.X_LS = PoseFromXyzRpy(xyz, rpy * (kPi / 180.0));
      c.xyz_m = xyz;
      c.rpy_deg = rpy;
      c.id += ":l" + std::to_string(study.candidates.size());  // a listed one is unique by its place
      c.sensor.name = c.id;
      study.candidates.push_back(c);
    }
  }
  // ids are unique: a repeated axis value would make two candidates one
  std::set<std::string> ids;
  for (const Candidate& c : study.candidates) {
    if (!ids.insert(c.id).second) reader.Fail(field, "candidate '" + c.id + "' appears twice (a repeated axis value?)");
  }
}

// the obstacle of a variant, moved and resized
void ApplyObstacle(YamlReader& reader, const Field& field, Scenario& scenario) {
  const auto map = reader.Map(field, {"height_m", "x_m", "y_m"});
  if (!map) return;
  SceneObject* obstacle = nullptr;
  for (SceneObject& object : scenario.scene.objects) {
    if (object.name == "obstacle") obstacle = &object;
  }
  Box* box = obstacle != nullptr ? std::get_if<Box>(&obstacle->shape) : nullptr;
  if (box == nullptr) {
    reader.Fail(field, "the variant's scene has no box named 'obstacle' to change");
    return;
  }
  if (const auto height_m = reader.Number((*map)["height_m"], PositiveNumber("m"))) {
    box->size_m.z() = *height_m;
    obstacle->X_WO.translation().z() = *height_m / 2;
  }
  if (const auto x_m = reader.Number((*map)["x_m"])) obstacle->X_WO.translation().x() = *x_m;
  if (const auto y_m = reader.Number((*map)["y_m"])) obstacle->X_WO.translation().y() = *y_m;
}

void ReadVariants(YamlReader& reader, const Field& field, const std::optional<Scenario>& base,
                  const std::filesystem::path& base_dir, StudyConfig& study) {
  const auto items = reader.List(field, "a list of scene variants {name, builtin | scenario, obstacle}");
  if (!items) return;
  if (items->empty()) reader.Fail(field, "expected at least one scene variant, got an empty list");
  std::set<std::string> names;
  for (const Field& item : *items) {
    const auto map = reader.Map(item, {"name", "builtin", "scenario", "obstacle"});
    if (!map) continue;
    const auto name = reader.String((*map)["name"]);
    if (!name) {
      reader.Fail(item, "expected a name");
      continue;
    }
    if (!names.insert(*name).second) reader.Fail((*map)["name"], "scene variant '" + *name + "' appears twice");
    SceneVariant variant{*name, {}};
    if (const Field file = (*map)["scenario"]) {
      // a whole scenario of its own: its scene, robot and timing
      const auto text = reader.String(file);
      if (!text) continue;
      try {
        variant.scenario = LoadScenarioFile(ResolveScenarioPath(base_dir, *text).string());
      } catch (const InputError& error) {
        for (const std::string& problem : error.problems()) reader.Fail(file, "the variant does not load: " + problem);
        continue;
      }
    } else if (base) {
      variant.scenario = *base;
      if (const Field builtin = (*map)["builtin"]) {
        const auto scene = reader.String(builtin);
        if (!scene) continue;
        try {
          variant.scenario.scene = MakeBuiltinScene(*scene);
          variant.scenario.builtin_scene = *scene;
        } catch (const InputError& error) {
          for (const std::string& problem : error.problems()) reader.Fail(builtin, problem);
          continue;
        }
      }
    } else {
      continue;  // the base did not load: already reported
    }
    if (const Field obstacle = (*map)["obstacle"]) ApplyObstacle(reader, obstacle, variant.scenario);
    variant.scenario.sensors.clear();
    if (variant.scenario.robot) variant.scenario.robot->strategy.reset();  // the walk goes on whatever is seen
    if (!variant.scenario.robot) reader.Fail(item, "the variant has no robot: its candidates would not move");
    study.variants.push_back(std::move(variant));
  }
}

}  // namespace

std::vector<Candidate> ReadStudyCandidates(YamlReader& reader, const Field& field, bool allow_large) {
  StudyConfig study;
  ReadCandidates(reader, field, study, allow_large);
  return study.candidates;
}

std::optional<Candidate> MakeStudyCandidate(const std::string& type, const std::string& link, double along_m,
                                            double forward_m, double pitch_deg, double yaw_deg) {
  const auto spec = SpecOf(type);
  if (!spec) return std::nullopt;
  return MakeCandidate(*spec, type, link, along_m, forward_m, pitch_deg, yaw_deg);
}

StudyConfig LoadStudyFile(const std::string& path, bool allow_large) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) throw InputError(path + ": cannot read the study file: no such file");
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  YamlReader reader(path);
  const YAML::Node document = reader.Parse(text.str());
  StudyConfig study;
  study.source = path;
  const auto top = reader.Map(reader.Root(document),
                              {"proxsim_study", "mode", "base", "candidates", "scenes", "seeds", "hazards", "select"},
                              "a study map starting with 'proxsim_study: 1'");
  if (!top) throw InputError(reader.Problems());
  if (const auto version = reader.Count((*top)["proxsim_study"]); !version || *version != 1) {
    if (!(*top)["proxsim_study"]) reader.Fail((*top)["proxsim_study"], "expected proxsim_study: 1");
    else if (version) reader.Fail((*top)["proxsim_study"], "expected 1, the only study schema");
  }

  // detection, the default; outcome studies are read by LoadOutcomeStudyFile
  if (const auto mode = reader.String((*top)["mode"]); mode && *mode != "detection") {
    reader.Fail((*top)["mode"], "expected detection (the default) or outcomes, got '" + *mode + "'");
  }

  // the base scenario
  const std::filesystem::path base_dir = std::filesystem::path(path).parent_path();
  std::optional<Scenario> base;
  if (reader.Require((*top)["base"], "the base scenario's file")) {
    if (const auto base_path = reader.String((*top)["base"])) {
      try {
        base = LoadScenarioFile(ResolveScenarioPath(base_dir, *base_path).string());
      } catch (const InputError& e) {
        for (const std::string& problem : e.problems()) reader.Fail((*top)["base"], "the base does not load: " + problem);
      }
    }
  }
  if (reader.Require((*top)["candidates"], "the candidate mountings (axes or a list)")) {
    ReadCandidates(reader, (*top)["candidates"], study, allow_large);
  }
  if ((*top)["scenes"]) {
    ReadVariants(reader, (*top)["scenes"], base, base_dir, study);
  } else if (base) {
    study.variants.push_back({"base", *base});  // the base's own scene only
    study.variants.back().scenario.sensors.clear();
    if (study.variants.back().scenario.robot) study.variants.back().scenario.robot->strategy.reset();
  }
  // a study walks its robots itself: no caller sets a co-simulated robot's state
  for (const SceneVariant& variant : study.variants) {
    if (variant.scenario.robot && variant.scenario.robot->locomotion == LocomotionSource::kExternal) {
      reader.Fail((*top)["scenes"] ? (*top)["scenes"] : (*top)["base"],
                  "scene '" + variant.name + "': robot.locomotion: external has no caller in a study; expected gait");
    }
  }

  for (double seed : NumberAxis(reader, (*top)["seeds"], {1.0})) {
    if (seed < 0 || seed != std::floor(seed)) {
      reader.Fail((*top)["seeds"], "expected whole numbers >= 0 as seeds");
      break;
    }
    study.seeds.push_back(static_cast<std::uint64_t>(seed));
  }
  if ((*top)["hazards"]) {
    study.hazards = TextAxis(reader, (*top)["hazards"], "object-name prefixes");
  } else {
    study.hazards = {"obstacle"};
  }
  if (const auto select = reader.Map((*top)["select"], {"sensors", "types"})) {
    if (const auto k = reader.Count((*select)["sensors"])) {
      if (*k < 1) reader.Fail((*select)["sensors"], "expected at least 1 sensor to select");
      study.select_sensors = static_cast<int>(*k);
    }
    if ((*select)["types"]) {
      study.select_types = TextAxis(reader, (*select)["types"], "the sensor types or parts to choose from");
      for (const std::string& type : study.select_types) {
        const bool studied = std::any_of(study.candidates.begin(), study.candidates.end(),
                                         [&](const Candidate& c) { return c.type == type; });
        if (!studied) reader.Fail((*select)["types"], "'" + type + "' is not the type of any candidate");
      }
    }
  }
  if (!reader.HasProblems() && study.candidates.empty()) reader.Fail((*top)["candidates"], "no candidate to study");
  // the whole study's size, before any world is built or any run starts
  const double runs = static_cast<double>(study.candidates.size()) * study.variants.size() * study.seeds.size();
  if (!allow_large && runs > static_cast<double>(kMaxStudyRuns)) {
    reader.Fail((*top)["seeds"], std::to_string(study.candidates.size()) + " candidates x " +
                                     std::to_string(study.variants.size()) + " scenes x " +
                                     std::to_string(study.seeds.size()) + " seeds = " +
                                     std::to_string(static_cast<std::uint64_t>(runs)) + " runs; expected at most " +
                                     std::to_string(kMaxStudyRuns) + " (pass --allow-large to run it anyway)");
  }
  if (reader.HasProblems()) throw InputError(reader.Problems());
  return study;
}

}  // namespace proxsim
