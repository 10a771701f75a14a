#include "output/zones_npy.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "core/atomic_file.h"
#include "output/npy_files.h"
#include "sensors/measured_point.h"
#include "sensors/multizone.h"

namespace proxsim {

bool ZonesNpyWriter::Needed(const Scenario& scenario) {
  return std::any_of(scenario.sensors.begin(), scenario.sensors.end(),
                     [](const SensorConfig& sensor) { return sensor.spec.zones.has_value(); });
}

ZonesNpyWriter::ZonesNpyWriter(const std::string& out_dir, const Scenario& scenario)
    : dir_((std::filesystem::path(out_dir) / "zones").string()), scenario_(scenario) {
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    const auto& zones = scenario.sensors[i].spec.zones;
    if (!zones) continue;
    sensors_.push_back({.index = i, .folder = SensorFolderName(scenario.sensors[i].name, i), .zones = ZoneCount(*zones),
                        .targets = zones->targets, .t_s = {}, .d_m = {}, .p_W = {}, .status = {}, .target_count = {}});
  }
  // before the run writes anything: a linked folder here once got the arrays written through it
  RefuseLinkedSensorFolders(dir_, sensors_);
}

void ZonesNpyWriter::Add(const SampleFrame& frame) {
  for (Sensor& sensor : sensors_) {
    const SensorSample& sample = frame.sensors[sensor.index];
    if (sample.reading.status == ReadingStatus::kNotSampled) continue;  // its own samples only
    sensor.t_s.push_back(frame.t_s);
    // the zones' slots, zones × targets: a target where the part reports one,
    // its zone's code in the first slot of a zone without, "no target" elsewhere
    const auto slots = static_cast<std::size_t>(sensor.zones * sensor.targets);
    const std::size_t first = sensor.status.size();
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    sensor.d_m.resize(first + slots, 0.0);
    sensor.status.resize(first + slots, kZoneNoTarget);
    sensor.p_W.resize(3 * (first + slots), kNaN);
    sensor.target_count.resize(sensor.target_count.size() + static_cast<std::size_t>(sensor.zones), 0);
    std::uint8_t* counts = &sensor.target_count[sensor.target_count.size() - static_cast<std::size_t>(sensor.zones)];
    for (const Measurement& measurement : sample.measurements) {
      const std::size_t slot = first + static_cast<std::size_t>(measurement.group * sensor.targets + measurement.rank);
      sensor.status[slot] = measurement.code;
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

void ZonesNpyWriter::Commit() {
  RefuseLinkedSensorFolders(dir_, sensors_);
  nlohmann::json codes = nlohmann::json::object();
  for (const std::uint8_t code : ZoneStatusCodes()) codes[std::to_string(code)] = ZoneStatusName(code);
  nlohmann::json sensors = nlohmann::json::object();
  for (const Sensor& sensor : sensors_) {
    const std::string folder = dir_ + "/" + sensor.folder;
    std::filesystem::create_directories(folder);
    const auto samples = static_cast<std::int64_t>(sensor.t_s.size());
    WriteNpyArray(folder + "/t_s.npy", "<f8", {samples}, sensor.t_s);
    WriteNpyArray(folder + "/d_m.npy", "<f8", {samples, sensor.zones, sensor.targets}, sensor.d_m);
    WriteNpyArray(folder + "/p_W.npy", "<f8", {samples, sensor.zones, sensor.targets, 3}, sensor.p_W);
    WriteNpyArray(folder + "/status.npy", "|u1", {samples, sensor.zones, sensor.targets}, sensor.status);
    WriteNpyArray(folder + "/target_count.npy", "|u1", {samples, sensor.zones}, sensor.target_count);
    const ZoneSpec& zones = *scenario_.sensors[sensor.index].spec.zones;
    sensors[scenario_.sensors[sensor.index].name] = {
        {"folder", sensor.folder},
        {"samples", samples},
        {"zones", {zones.nx, zones.ny}},
        {"targets", sensor.targets},
        {"fov_deg", {zones.fov_h_deg, zones.fov_v_deg}}};
  }
  const nlohmann::json columns = {
      {"sensors", sensors},
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
  WriteFileAtomically(dir_ + "/columns.json", columns.dump(1) + "\n");
}

void ZonesNpyWriter::AddToSummary(nlohmann::json& summary) const { summary["outputs"].push_back("zones/"); }

}  // namespace proxsim
