#include "output/measurements_npy.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "core/atomic_file.h"
#include "output/npy_files.h"
#include "sensors/measured_point.h"
#include "sensors/multizone.h"

namespace proxsim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool OfKind(const SensorConfig& sensor, MeasurementsNpyWriter::Kind kind) {
  return kind == MeasurementsNpyWriter::Kind::kZones ? sensor.spec.zones.has_value()
                                                     : sensor.spec.echoes != EchoSelection::kFirst;
}

}  // namespace

bool MeasurementsNpyWriter::Needed(const Scenario& scenario, Kind kind) {
  return std::any_of(scenario.sensors.begin(), scenario.sensors.end(),
                     [kind](const SensorConfig& sensor) { return OfKind(sensor, kind); });
}

MeasurementsNpyWriter::MeasurementsNpyWriter(const std::string& out_dir, const Scenario& scenario, Kind kind)
    : kind_(kind),
      dir_((std::filesystem::path(out_dir) / (kind == Kind::kZones ? "zones" : "echoes")).string()),
      scenario_(scenario) {
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    if (!OfKind(scenario.sensors[i], kind)) continue;
    const auto& zones = scenario.sensors[i].spec.zones;
    Sensor sensor{.index = i,
                  .folder = SensorFolderName(scenario.sensors[i].name, i),
                  .groups = kind == Kind::kZones ? ZoneCount(*zones) : 1,
                  .ranks = kind == Kind::kZones ? zones->targets : kMaxEchoes,
                  .t_s = {}, .d_m = {}, .signal = {}, .p_W = {}, .code = {}, .group_count = {}, .count = {}};
    sensors_.push_back(std::move(sensor));
  }
  // before the run writes anything: a linked folder here once got the arrays written through it
  RefuseLinkedSensorFolders(dir_, sensors_);
}

void MeasurementsNpyWriter::Add(const SampleFrame& frame) {
  const bool zones = kind_ == Kind::kZones;
  for (Sensor& sensor : sensors_) {
    const SensorSample& sample = frame.sensors[sensor.index];
    if (sample.reading.status == ReadingStatus::kNotSampled) continue;  // its own samples only
    sensor.t_s.push_back(frame.t_s);
    // the sample's slots, groups × ranks: each measurement in its group's
    // rank; an empty slot holds "no target" (a zone: distance 0, code
    // kZoneNoTarget, no point) or "no echo" (a beam: NaN)
    const auto slots = static_cast<std::size_t>(sensor.groups * sensor.ranks);
    const std::size_t first = sensor.d_m.size();
    sensor.d_m.resize(first + slots, zones ? 0.0 : kNaN);
    if (zones) {
      sensor.code.resize(first + slots, kZoneNoTarget);
      sensor.p_W.resize(3 * (first + slots), kNaN);
      sensor.group_count.resize(sensor.group_count.size() + static_cast<std::size_t>(sensor.groups), 0);
    } else {
      sensor.signal.resize(first + slots, kNaN);
      sensor.count.push_back(static_cast<std::uint8_t>(sample.measurements.size()));
    }
    std::uint8_t* counts =
        zones ? &sensor.group_count[sensor.group_count.size() - static_cast<std::size_t>(sensor.groups)] : nullptr;
    for (const Measurement& measurement : sample.measurements) {
      const std::size_t slot = first + static_cast<std::size_t>(measurement.group * sensor.ranks + measurement.rank);
      if (!zones) {
        // a beam's echoes as the part hears them, nearest first
        sensor.d_m[slot] = measurement.d_m;
        sensor.signal[slot] = measurement.signal;
        continue;
      }
      // a zone's code in its first slot without a target, its targets' codes in theirs
      sensor.code[slot] = measurement.code;
      if (!measurement.detected()) continue;
      ++counts[measurement.group];
      sensor.d_m[slot] = measurement.d_m;
      // along its zone's axis, as the map and the profile place it
      if (measurement.d_m > 0) {
        const Vec3 p_W = measurement.p_W();
        for (int c = 0; c < 3; ++c) sensor.p_W[3 * slot + static_cast<std::size_t>(c)] = p_W[c];
      }
    }
  }
}

namespace {

// zones/columns.json: the sensors' folders, the zone order, the columns, the status codes' names
nlohmann::json ZonesColumns(nlohmann::json sensors) {
  nlohmann::json codes = nlohmann::json::object();
  for (const std::uint8_t code : ZoneStatusCodes()) codes[std::to_string(code)] = ZoneStatusName(code);
  return {
      {"sensors", std::move(sensors)},
      {"zone_order", "zone z = row * nx + column; row 0 at the top (+z), column 0 on the left (+y), seen along the sensor's +x"},
      {"columns",
       {{{"name", "t_s"}, {"dtype", "float64"}, {"shape", "samples"}, {"unit", "s"}, {"meaning", "the sample's time"}},
        {{"name", "d_m"}, {"dtype", "float64"}, {"shape", "samples x zones x targets"}, {"unit", "m"},
         {"meaning", "the target's reported distance, nearest first; 0 where the zone has no such target"}},
        {{"name", "p_W"}, {"dtype", "float64"}, {"shape", "samples x zones x targets x 3"}, {"unit", "m, world"},
         {"meaning", "the target's measured point: the sensor's origin + d_m along its zone's axis; NaN without a target"}},
        {{"name", "status"}, {"dtype", "uint8"}, {"shape", "samples x zones x targets"}, {"unit", ""},
         {"meaning", "ST's target status code (UM2884 Table 4): see status_codes"}},
        {{"name", "target_count"}, {"dtype", "uint8"}, {"shape", "samples x zones"}, {"unit", ""},
         {"meaning", "valid targets found in the zone"}}}},
      {"status_codes", codes}};
}

// echoes/columns.json: the sensors' folders, the most echoes kept, the columns
nlohmann::json EchoesColumns(nlohmann::json sensors) {
  return {
      {"sensors", std::move(sensors)},
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
}

}  // namespace

void MeasurementsNpyWriter::Commit() {
  RefuseLinkedSensorFolders(dir_, sensors_);
  const bool zones = kind_ == Kind::kZones;
  nlohmann::json sensors = nlohmann::json::object();
  for (const Sensor& sensor : sensors_) {
    const std::string folder = dir_ + "/" + sensor.folder;
    std::filesystem::create_directories(folder);
    const auto samples = static_cast<std::int64_t>(sensor.t_s.size());
    WriteNpyArray(folder + "/t_s.npy", "<f8", {samples}, sensor.t_s);
    // a zone's slots (samples, zones, targets), a beam's (samples, echoes)
    const std::vector<std::int64_t> slots = zones ? std::vector<std::int64_t>{samples, sensor.groups, sensor.ranks}
                                                  : std::vector<std::int64_t>{samples, sensor.ranks};
    WriteNpyArray(folder + "/d_m.npy", "<f8", slots, sensor.d_m);
    const SensorConfig& config = scenario_.sensors[sensor.index];
    if (zones) {
      WriteNpyArray(folder + "/p_W.npy", "<f8", {samples, sensor.groups, sensor.ranks, 3}, sensor.p_W);
      WriteNpyArray(folder + "/status.npy", "|u1", slots, sensor.code);
      WriteNpyArray(folder + "/target_count.npy", "|u1", {samples, sensor.groups}, sensor.group_count);
      const ZoneSpec& spec = *config.spec.zones;
      sensors[config.name] = {{"folder", sensor.folder},
                              {"samples", samples},
                              {"zones", {spec.nx, spec.ny}},
                              {"targets", sensor.ranks},
                              {"fov_deg", {spec.fov_h_deg, spec.fov_v_deg}}};
    } else {
      WriteNpyArray(folder + "/signal.npy", "<f8", slots, sensor.signal);
      WriteNpyArray(folder + "/count.npy", "|u1", {samples}, sensor.count);
      sensors[config.name] = {{"folder", sensor.folder},
                              {"samples", samples},
                              {"echoes", EchoSelectionName(config.spec.echoes)},
                              {"echo_separation_m", config.spec.echo_separation_m}};
    }
  }
  const nlohmann::json columns = zones ? ZonesColumns(std::move(sensors)) : EchoesColumns(std::move(sensors));
  WriteFileAtomically(dir_ + "/columns.json", columns.dump(1) + "\n");
}

void MeasurementsNpyWriter::AddToSummary(nlohmann::json& summary) const {
  summary["outputs"].push_back(kind_ == Kind::kZones ? "zones/" : "echoes/");
}

}  // namespace proxsim
