#include "fidelity/fidelity_run.h"

#include <cstdio>

#include "sensors/multizone.h"

namespace proxsim {

namespace {

// "+0.012" or "-" for a statistic that is undefined (no reading both call valid)
std::string SummaryNumber(const char* format, double value) {
  if (value != value) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace

FidelityInputs LoadFidelityInputs(const std::string& path, std::optional<bool> simulate_noise) {
  FidelityInputs inputs{.config = LoadFidelityFile(path), .recording = {}};
  FidelityConfig& config = inputs.config;
  if (simulate_noise) config.simulate_noise = *simulate_noise;
  SensorConfig& sensor = config.scenario.sensors.front();
  PrepareFidelitySensor(sensor, config.simulate_noise);
  inputs.recording = LoadRecording(config.recording_path, ReportedZoneCount(sensor));
  return inputs;
}

std::vector<ComparedReading> CompareReadings(const Recording& recording, const ReplayedReadings& replayed,
                                             const SensorSpec& spec, const std::vector<double>& band_edges_m) {
  std::vector<ComparedReading> compared(recording.valid.size());
  const auto zones = static_cast<std::size_t>(recording.zone_count);
  for (std::size_t i = 0; i < compared.size(); ++i) {
    ComparedReading& r = compared[i];
    r.zone = static_cast<int>(i % zones);
    r.ring = spec.zones ? ZoneRing(spec.zones->nx, spec.zones->ny, r.zone) : 0;
    r.recorded_valid = recording.valid[i] != 0;
    r.recorded_d_m = recording.d_m[i];
    r.band = r.recorded_valid ? RangeBand(band_edges_m, r.recorded_d_m) : -1;
    r.simulated_valid = replayed.valid[i] != 0;
    r.simulated_d_m = replayed.d_m[i];
  }
  return compared;
}

FidelityComparison CompareFidelity(const FidelityInputs& inputs, int threads) {
  FidelityComparison comparison;
  const Scenario& scenario = inputs.config.scenario;
  comparison.replayed = ReplayRecording(scenario, inputs.recording, threads);
  comparison.compared = CompareReadings(inputs.recording, comparison.replayed, scenario.sensors.front().spec,
                                        inputs.config.band_edges_m);
  comparison.rows = FidelityTables(comparison.compared);
  return comparison;
}

std::string FidelitySummary(const FidelityInputs& inputs, const FidelityComparison& comparison) {
  const FidelityConfig& config = inputs.config;
  const SensorConfig& sensor = config.scenario.sensors.front();
  std::string text;
  char line[256];
  std::snprintf(line, sizeof line, "proxsim fidelity: %s — %zu readings of %zu samples (%s, %d zone%s), model noise %s\n",
                config.source.c_str(), comparison.compared.size(), inputs.recording.sample_count(),
                sensor.spec.part.empty() ? SensorTypeName(sensor.spec.type) : sensor.spec.part.c_str(),
                inputs.recording.zone_count, inputs.recording.zone_count == 1 ? "" : "s",
                config.simulate_noise ? "on" : "off");
  text += line;
  std::snprintf(line, sizeof line, "  %-14s %8s %10s %8s %10s %8s %9s %11s %10s %9s %11s %10s\n", "group", "readings",
                "both valid", "rec only", "model only", "neither", "agreement", "median err", "p90 |err|", "bias",
                "median rel", "p90 |rel|");
  text += line;
  for (const FidelityRow& row : comparison.rows) {
    if (row.table != "all" && row.table != "ring" && row.table != "band") continue;
    const std::string group = row.table == "all"    ? std::string("all")
                              : row.table == "ring" ? "ring " + std::to_string(row.ring)
                                                    : "band " + RangeBandName(config.band_edges_m, row.band);
    const FidelityStats& s = row.stats;
    std::snprintf(line, sizeof line, "  %-14s %8zu %10zu %8zu %10zu %8zu %9s %9s m %8s m %7s m %9s %% %8s %%\n",
                  group.c_str(), s.count, s.both_valid, s.recorded_only, s.simulated_only, s.both_invalid,
                  SummaryNumber("%.3f", s.validity_agreement).c_str(),
                  SummaryNumber("%+.4f", s.median_error_m).c_str(), SummaryNumber("%.4f", s.p90_abs_error_m).c_str(),
                  SummaryNumber("%+.4f", s.bias_m).c_str(), SummaryNumber("%+.2f", 100 * s.median_rel_error).c_str(),
                  SummaryNumber("%.2f", 100 * s.p90_abs_rel_error).c_str());
    text += line;
  }
  return text;
}

}  // namespace proxsim
