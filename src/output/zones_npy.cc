#include "output/zones_npy.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "core/atomic_file.h"
#include "sensors/measured_point.h"
#include "sensors/multizone.h"

namespace proxsim {

namespace {

// a sensor's name as a folder when it is a plain file name, else its index
std::string FolderFor(const std::string& name, std::size_t index) {
  const bool plain = !name.empty() && name != "." && name != ".." &&
                     std::all_of(name.begin(), name.end(), [](char c) {
                       return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                              c == '-' || c == '.';
                     });
  return plain ? name : "sensor_" + std::to_string(index);
}

template <typename T>
void WriteArray(const std::string& path, const char* descr, const std::vector<std::int64_t>& shape,
                const std::vector<T>& values) {
  std::string bytes = NpyArrayHeader(descr, shape);
  bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  WriteFileAtomically(path, bytes);
}

}  // namespace

std::string NpyArrayHeader(const char* descr, const std::vector<std::int64_t>& shape) {
  std::string dims;
  for (const std::int64_t n : shape) dims += std::to_string(n) + ",";
  if (shape.size() > 1) dims.pop_back();  // (n,) for one dimension, (a,b,c) for more
  std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" + dims + "), }";
  // magic 6 + version 2 + length 2 + dict + '\n', padded to a multiple of 64
  const std::size_t total = (10 + dict.size() + 1 + 63) / 64 * 64;
  const std::size_t length = total - 10;
  dict.resize(length - 1, ' ');
  std::string header = "\x93NUMPY";
  header += '\x01';
  header += '\x00';
  header += static_cast<char>(length & 0xFF);
  header += static_cast<char>(length >> 8);
  header += dict;
  header += '\n';
  return header;
}

bool ZonesNpyWriter::Needed(const Scenario& scenario) {
  return std::any_of(scenario.sensors.begin(), scenario.sensors.end(),
                     [](const SensorConfig& sensor) { return sensor.spec.zones.has_value(); });
}

ZonesNpyWriter::ZonesNpyWriter(const std::string& out_dir, const Scenario& scenario)
    : dir_((std::filesystem::path(out_dir) / "zones").string()), scenario_(scenario) {
  for (std::size_t i = 0; i < scenario.sensors.size(); ++i) {
    const auto& zones = scenario.sensors[i].spec.zones;
    if (!zones) continue;
    sensors_.push_back({.index = i, .folder = FolderFor(scenario.sensors[i].name, i), .zones = ZoneCount(*zones),
                        .targets = zones->targets, .t_s = {}, .d_m = {}, .p_W = {}, .status = {}, .target_count = {}});
  }
}

void ZonesNpyWriter::Add(const SampleFrame& frame) {
  for (Sensor& sensor : sensors_) {
    const SensorSample& sample = frame.sensors[sensor.index];
    if (sample.reading.status == ReadingStatus::kNotSampled) continue;  // its own samples only
    sensor.t_s.push_back(frame.t_s);
    for (std::size_t k = 0; k < sample.zones.targets.size(); ++k) {
      const ZoneTarget& target = sample.zones.targets[k];
      sensor.d_m.push_back(target.d_m);
      sensor.status.push_back(target.status);
      // along its zone's axis, as the map and the profile place it
      const Vec3 p_W = target.d_m > 0 ? MeasuredPoint_W(sample.p_WS, sample.zone_dir_W[k / sensor.targets], target.d_m)
                                      : Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
      sensor.p_W.insert(sensor.p_W.end(), {p_W.x(), p_W.y(), p_W.z()});
    }
    sensor.target_count.insert(sensor.target_count.end(), sample.zones.target_count.begin(),
                               sample.zones.target_count.end());
  }
}

void ZonesNpyWriter::Commit() {
  nlohmann::json codes = nlohmann::json::object();
  for (const std::uint8_t code : ZoneStatusCodes()) codes[std::to_string(code)] = ZoneStatusName(code);
  nlohmann::json sensors = nlohmann::json::object();
  for (const Sensor& sensor : sensors_) {
    const std::string folder = dir_ + "/" + sensor.folder;
    std::filesystem::create_directories(folder);
    const auto samples = static_cast<std::int64_t>(sensor.t_s.size());
    WriteArray(folder + "/t_s.npy", "<f8", {samples}, sensor.t_s);
    WriteArray(folder + "/d_m.npy", "<f8", {samples, sensor.zones, sensor.targets}, sensor.d_m);
    WriteArray(folder + "/p_W.npy", "<f8", {samples, sensor.zones, sensor.targets, 3}, sensor.p_W);
    WriteArray(folder + "/status.npy", "|u1", {samples, sensor.zones, sensor.targets}, sensor.status);
    WriteArray(folder + "/target_count.npy", "|u1", {samples, sensor.zones}, sensor.target_count);
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
