// Reading a fidelity file: its own keys here, its `scene:` and `sensors:`
// handed to the scenario parser as a scenario document made of the file's
// own nodes (so its messages keep the file's lines), every problem of both
// thrown together.
#include "fidelity/fidelity_config.h"

#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "core/regular_file.h"
#include "scenario/scenario_sections.h"
#include "scenario/yaml_reader.h"

namespace proxsim {

namespace {

// A fidelity file and a recording are small text files; this refuses /dev/zero and the like.
constexpr unsigned long long kMaxFidelityYamlBytes = 16ull << 20;
constexpr unsigned long long kMaxRecordingBytes = 2ull << 30;

// The scenario keys a fidelity file shares with a scenario: passed to its parser as they are.
constexpr const char* kScenarioKeys[] = {"proxsim", "seed", "scene", "sensors"};

// bands_m: ascending edges > 0
std::vector<double> ReadBandEdges(YamlReader& reader, const Field& field) {
  if (!field) return DefaultBandEdges_m();
  const auto items = reader.List(field, "a list of range band edges in metres, ascending, > 0");
  if (!items) return DefaultBandEdges_m();
  std::vector<double> edges_m;
  for (const Field& item : *items) {
    const auto edge_m = reader.Number(item, PositiveNumber("m"));
    if (!edge_m) return DefaultBandEdges_m();
    if (!edges_m.empty() && !(*edge_m > edges_m.back())) {
      reader.Fail(item, "expected edges in ascending order, got " + DescribeNode(item.node) + " after " +
                            std::to_string(edges_m.back()));
      return DefaultBandEdges_m();
    }
    edges_m.push_back(*edge_m);
  }
  if (edges_m.empty()) reader.Fail(field, "expected at least one range band edge in metres, got an empty list");
  return edges_m.empty() ? DefaultBandEdges_m() : edges_m;
}

}  // namespace

std::vector<double> DefaultBandEdges_m() { return {0.5, 1.0, 1.5, 2.0, 3.0, 4.0}; }

FidelityConfig LoadFidelityFile(const std::string& path) {
  if (const std::string problem = RegularFileProblem(path, kMaxFidelityYamlBytes); !problem.empty())
    throw InputError(problem + " (the fidelity file)");
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  YamlReader reader(path);
  const YAML::Node document = reader.Parse(text.str());
  if (!document.IsDefined() || document.IsNull()) {
    reader.FailFile("the file is empty; expected a map starting with 'proxsim: 1' (docs/fidelity.md)");
    throw InputError(reader.Problems());
  }

  FidelityConfig config;
  config.source = path;
  const auto top = reader.Map(reader.Root(document),
                              {"proxsim", "seed", "scene", "sensors", "recording", "simulate_noise", "bands_m"},
                              "a map of fidelity keys (proxsim, seed, scene, sensors, recording, simulate_noise, "
                              "bands_m)");
  if (!top) throw InputError(reader.Problems());

  // one sensor: the recording is of one part
  if (const auto sensors = reader.List((*top)["sensors"], "a list of one sensor, as in a scenario");
      sensors && sensors->size() > 1) {  // none: the scenario parser says so
    reader.Fail((*top)["sensors"], "expected exactly one sensor (the recorded part), got " +
                                       std::to_string(sensors->size()));
  }
  // the recording, relative to this file
  if (reader.Require((*top)["recording"], "recording: the CSV file of poses and readings (docs/fidelity.md)")) {
    if (const auto csv = reader.String((*top)["recording"])) {
      config.recording_path = ResolveScenarioPath(std::filesystem::path(path).parent_path(), *csv).string();
      if (const std::string problem = RegularFileProblem(config.recording_path, kMaxRecordingBytes); !problem.empty())
        reader.Fail((*top)["recording"], "expected the recording's CSV file (relative paths start from this "
                                         "file's folder): " + problem);
    }
  }
  config.simulate_noise = reader.Bool((*top)["simulate_noise"]).value_or(false);
  config.band_edges_m = ReadBandEdges(reader, (*top)["bands_m"]);

  // the scene and the sensor, by the scenario parser, from the file's own nodes
  const YAML::Node& top_node = document;
  YAML::Node scenario_document(YAML::NodeType::Map);
  for (const char* key : kScenarioKeys) {
    if (top_node[key]) scenario_document[key] = top_node[key];
  }
  std::vector<std::string> problems = reader.Problems();
  try {
    config.scenario = LoadScenarioNode(scenario_document, path);
  } catch (const InputError& error) {
    problems.insert(problems.end(), error.problems().begin(), error.problems().end());
  }
  if (!problems.empty()) throw InputError(problems);
  return config;
}

void PrepareFidelitySensor(SensorConfig& sensor, bool simulate_noise) {
  sensor.rate_hz = 0.0;
  sensor.latency_s = 0.0;
  sensor.flight_time = false;
  sensor.fire_offset_s = 0.0;
  if (simulate_noise) return;
  // noise off: no spread and no dropout; a mean (a bias the spec states) and
  // the resolution (what the part reports) stay part of the model
  SensorSpec& spec = sensor.spec;
  spec.noise.sigma = 0.0;
  spec.noise.dropout = 0.0;
  spec.sigma_table.clear();
  for (LookupRow& row : spec.lookup_table) row.noise_fraction = 0.0;
}

}  // namespace proxsim
