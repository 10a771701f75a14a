#include "fidelity/fidelity_outputs.h"

#include <filesystem>

#include "core/atomic_file.h"
#include "core/number_format.h"
#include "core/text_fields.h"
#include "sensors/sensor_spec.h"

namespace proxsim {

namespace {

// A statistic in JSON: null where undefined (no reading both call valid).
nlohmann::json JsonNumber(double value) { return value == value ? nlohmann::json(value) : nlohmann::json(nullptr); }

// A row's group label in JSON and CSV: -1 / -2 mean "not by this" (fidelity_stats.h)
nlohmann::json JsonIndex(int index, int none) { return index == none ? nlohmann::json(nullptr) : nlohmann::json(index); }

void AppendIndex(std::string& line, int index, int none) {
  if (index != none) AppendInteger(line, index);
}

// The sensor as the comparison used it, for the echo.
nlohmann::json SensorJson(const SensorConfig& sensor) {
  nlohmann::json json = {{"name", sensor.name},
                         {"type", SensorTypeName(sensor.spec.type)},
                         {"part", sensor.spec.part},
                         {"range_m", {sensor.spec.min_range_m, sensor.spec.max_range_m}}};
  if (const auto& zones = sensor.spec.zones) {
    json["zones"] = {zones->nx, zones->ny};
    json["distance"] = zones->perpendicular ? "perpendicular" : "radial";
  }
  return json;
}

}  // namespace

nlohmann::json FidelityJson(const FidelityConfig& config, const Recording& recording, std::span<const FidelityRow> rows) {
  nlohmann::json tables = nlohmann::json::array();
  for (const FidelityRow& row : rows) {
    const FidelityStats& s = row.stats;
    tables.push_back({{"table", row.table},
                      {"zone", JsonIndex(row.zone, -1)},
                      {"ring", JsonIndex(row.ring, -1)},
                      {"band", JsonIndex(row.band, -2)},
                      {"band_name", row.band == -2 ? nlohmann::json(nullptr)
                                                   : nlohmann::json(RangeBandName(config.band_edges_m, row.band))},
                      {"count", s.count},
                      {"both_valid", s.both_valid},
                      {"recorded_only", s.recorded_only},
                      {"simulated_only", s.simulated_only},
                      {"both_invalid", s.both_invalid},
                      {"validity_agreement", JsonNumber(s.validity_agreement)},
                      {"median_error_m", JsonNumber(s.median_error_m)},
                      {"p90_abs_error_m", JsonNumber(s.p90_abs_error_m)},
                      {"bias_m", JsonNumber(s.bias_m)},
                      {"median_rel_error", JsonNumber(s.median_rel_error)},
                      {"p90_abs_rel_error", JsonNumber(s.p90_abs_rel_error)}});
  }
  const SensorConfig& sensor = config.scenario.sensors.front();
  return {{"proxsim", PROXSIM_VERSION},
          {"fidelity_file", config.source},
          {"recording", recording.source},
          {"sensor", SensorJson(sensor)},
          {"simulate_noise", config.simulate_noise},
          {"seed", config.scenario.seed},
          {"samples", recording.sample_count()},
          {"zones", recording.zone_count},
          {"band_edges_m", config.band_edges_m},
          {"error", "simulated - recorded distance, m, over the readings both call valid"},
          {"rings", "ring 0: the centre zones (the middle 2x2 of an even grid); one more per ring outwards"},
          {"tables", tables}};
}

void WriteFidelityOutputs(const std::string& dir, const FidelityConfig& config, const Recording& recording,
                          const ReplayedReadings& replayed, std::span<const ComparedReading> compared,
                          std::span<const FidelityRow> rows) {
  const std::filesystem::path out(dir);
  WriteFileAtomically((out / "fidelity.json").string(), FidelityJson(config, recording, rows).dump(2) + "\n");

  std::string stats = "table,zone,ring,band,band_name,count,both_valid,recorded_only,simulated_only,both_invalid,"
                      "validity_agreement,median_error_m,p90_abs_error_m,bias_m,median_rel_error,p90_abs_rel_error\n";
  for (const FidelityRow& row : rows) {
    const FidelityStats& s = row.stats;
    stats += row.table + ",";
    AppendIndex(stats, row.zone, -1);
    stats += ',';
    AppendIndex(stats, row.ring, -1);
    stats += ',';
    AppendIndex(stats, row.band, -2);
    stats += ',';
    if (row.band != -2) AppendCsvField(stats, RangeBandName(config.band_edges_m, row.band));
    for (const std::size_t count : {s.count, s.both_valid, s.recorded_only, s.simulated_only, s.both_invalid}) {
      stats += ',';
      AppendInteger(stats, static_cast<long long>(count));
    }
    for (const double value : {s.validity_agreement, s.median_error_m, s.p90_abs_error_m, s.bias_m,
                               s.median_rel_error, s.p90_abs_rel_error}) {
      stats += ',';
      AppendNumber(stats, value);
    }
    stats += '\n';
  }
  WriteFileAtomically((out / "fidelity_stats.csv").string(), stats);

  std::string pairs = "sample,t_s,zone,ring,band,recorded_d_m,recorded_valid,simulated_d_m,simulated_valid,"
                      "simulated_status,error_m\n";
  for (std::size_t i = 0; i < compared.size(); ++i) {
    const ComparedReading& r = compared[i];
    const std::size_t sample = i / static_cast<std::size_t>(recording.zone_count);
    AppendInteger(pairs, static_cast<long long>(sample));
    pairs += ',';
    AppendNumber(pairs, recording.t_s[sample]);
    for (const int index : {r.zone, r.ring, r.band}) {
      pairs += ',';
      AppendInteger(pairs, index);
    }
    pairs += ',';
    AppendNumber(pairs, r.recorded_d_m);
    pairs += r.recorded_valid ? ",1," : ",0,";
    AppendNumber(pairs, r.simulated_d_m);
    pairs += r.simulated_valid ? ",1," : ",0,";
    pairs += replayed.status[i];
    pairs += ',';
    if (r.recorded_valid && r.simulated_valid) AppendNumber(pairs, r.simulated_d_m - r.recorded_d_m);
    pairs += '\n';
  }
  WriteFileAtomically((out / "fidelity_pairs.csv").string(), pairs);
}

}  // namespace proxsim
