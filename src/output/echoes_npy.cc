#include "output/echoes_npy.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "output/npy_files.h"

namespace proxsim {

namespace {
bool HasEchoes(const SensorConfig& sensor) { return sensor.spec.echoes != EchoSelection::kFirst; }
}  // namespace

bool EchoesNpyWriter::Needed(const Scenario& scenario) {
  return std::any_of(scenario.sensors.begin(), scenario.sensors.end(), HasEchoes);
}

EchoesNpyWriter::EchoesNpyWriter(const std::string& out_dir, const Scenario& scenario)
    : dir_((std::filesystem::path(out_dir) / "echoes").string()), scenario_(scenario) {
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    if (!HasEchoes(scenario.sensors[i])) continue;
    sensors_.push_back({.index = i, .folder = SensorFolderName(scenario.sensors[i].name, i), .t_s = {}, .d_m = {},
                        .signal = {}, .count = {}});
  }
  // before the run writes anything: a linked folder here once got the arrays written through it
  RefuseLinkedSensorFolders(dir_, sensors_);
}

void EchoesNpyWriter::Add(const SampleFrame& frame) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (Sensor& sensor : sensors_) {
    const SensorSample& sample = frame.sensors[sensor.index];
    if (sample.reading.status == ReadingStatus::kNotSampled) continue;  // its own samples only
    sensor.t_s.push_back(frame.t_s);
    // the echoes the beam reports, nearest first (sensors/measurement.h), NaN past the last
    const std::vector<Measurement>& echoes = sample.measurements;
    for (std::size_t k = 0; k < static_cast<std::size_t>(kMaxEchoes); ++k) {
      const bool heard = k < echoes.size();
      sensor.d_m.push_back(heard ? echoes[k].d_m : kNaN);
      sensor.signal.push_back(heard ? echoes[k].signal : kNaN);
    }
    sensor.count.push_back(static_cast<std::uint8_t>(echoes.size()));
  }
}

void EchoesNpyWriter::Commit() {
  RefuseLinkedSensorFolders(dir_, sensors_);
  nlohmann::json sensors = nlohmann::json::object();
  for (const Sensor& sensor : sensors_) {
    const std::string folder = dir_ + "/" + sensor.folder;
    std::filesystem::create_directories(folder);
    const auto samples = static_cast<std::int64_t>(sensor.t_s.size());
    WriteNpyArray(folder + "/t_s.npy", "<f8", {samples}, sensor.t_s);
    WriteNpyArray(folder + "/d_m.npy", "<f8", {samples, std::int64_t{kMaxEchoes}}, sensor.d_m);
    WriteNpyArray(folder + "/signal.npy", "<f8", {samples, std::int64_t{kMaxEchoes}}, sensor.signal);
    WriteNpyArray(folder + "/count.npy", "|u1", {samples}, sensor.count);
    const SensorSpec& spec = scenario_.sensors[sensor.index].spec;
    sensors[scenario_.sensors[sensor.index].name] = {{"folder", sensor.folder},
                                                      {"samples", samples},
                                                      {"echoes", EchoSelectionName(spec.echoes)},
                                                      {"echo_separation_m", spec.echo_separation_m}};
  }
  const nlohmann::json columns = {
      {"sensors", sensors},
      {"max_echoes", kMaxEchoes},
      {"columns",
       {{{"name", "t_s"}, {"dtype", "float64"}, {"shape", "samples"}, {"unit", "s"}, {"meaning", "the sample's time"}},
        {{"name", "d_m"}, {"dtype", "float64"}, {"shape", "samples x 4"}, {"unit", "m"},
         {"meaning", "the echoes' reported distances (each its nearest ray's arrival with its noise), nearest first; "
                     "NaN past the last echo"}},
        {{"name", "signal"}, {"dtype", "float64"}, {"shape", "samples x 4"}, {"unit", ""},
         {"meaning", "the echo's signal: the sum over its rays of the ray's weight (gain x solid angle, 1 over the "
                     "beam) times the returned energy (physical model) or the surface's reflectivity; NaN past the "
                     "last echo"}},
        {{"name", "count"}, {"dtype", "uint8"}, {"shape", "samples"}, {"unit", ""},
         {"meaning", "the echoes heard, at most 4"}}}}};
  WriteFileAtomically(dir_ + "/columns.json", columns.dump(1) + "\n");
}

void EchoesNpyWriter::AddToSummary(nlohmann::json& summary) const { summary["outputs"].push_back("echoes/"); }

}  // namespace proxsim
