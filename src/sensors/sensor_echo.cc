#include "sensors/sensor_echo.h"

namespace proxsim {

namespace {

nlohmann::json BeamJson(const BeamSpec& beam) {
  nlohmann::json pattern = "uniform";
  if (beam.pattern == BeamPattern::kGaussian) pattern = {{"gaussian", {{"width_deg", beam.width_deg}}}};
  if (beam.pattern == BeamPattern::kTable) pattern = {{"table", beam.table}};
  return {{"aperture_deg", beam.aperture_deg},
          {"rays", beam.rays},
          {"pattern", pattern},
          {"reach", beam.reach.empty() ? nlohmann::json(nullptr) : nlohmann::json(beam.reach)}};
}

}  // namespace

nlohmann::json SensorSpecJson(const SensorSpec& spec) {
  nlohmann::json lookup = nullptr;
  if (!spec.lookup_table.empty()) {
    lookup = nlohmann::json::array();
    for (const LookupRow& row : spec.lookup_table) lookup.push_back({row.distance_m, row.output, row.noise_fraction});
  }
  return {{"type", SensorTypeName(spec.type)},
          {"part", spec.part.empty() ? nlohmann::json(nullptr) : nlohmann::json(spec.part)},
          {"range_m", {spec.min_range_m, spec.max_range_m}},
          {"max_incidence_deg", spec.max_incidence_deg},
          {"noise",
           {{"model", NoiseModelName(spec.noise.model)},
            {"sigma", spec.noise.sigma},
            {"mean", spec.noise.mean},
            {"resolution_m", spec.noise.resolution_m},
            {"dropout", spec.noise.dropout},
            {"sigma_table", spec.sigma_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(spec.sigma_table)}}},
          {"echoes", EchoSelectionName(spec.echoes)},
          {"echo_separation_m", spec.echo_separation_m},
          {"distance_mode", spec.distance_mode.empty() ? nlohmann::json(nullptr) : nlohmann::json(spec.distance_mode)},
          {"roi", spec.roi_spads[0] > 0 ? nlohmann::json(spec.roi_spads) : nlohmann::json(nullptr)},
          {"timing_budget_ms", spec.timing_budget_ms > 0 ? nlohmann::json(spec.timing_budget_ms) : nlohmann::json(nullptr)},
          {"beam", spec.beam ? BeamJson(*spec.beam) : nlohmann::json(nullptr)},
          {"echo_model", spec.echo_model == EchoModel::kPhysical ? "physical" : "window"},
          {"echo_threshold", spec.echo_threshold},
          {"specular_exponent", spec.specular_exponent},
          {"use_material", spec.use_material},
          {"lookup_table", lookup},
          {"echo_timeout_s", spec.echo_timeout_s > 0 ? nlohmann::json(spec.echo_timeout_s) : nlohmann::json(nullptr)},
          {"range_table", spec.range_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(spec.range_table)},
          {"corner_range_table",
           spec.corner_range_table.empty() ? nlohmann::json(nullptr) : nlohmann::json(spec.corner_range_table)},
          {"zones", spec.zones ? nlohmann::json{spec.zones->nx, spec.zones->ny} : nlohmann::json(nullptr)},
          {"fov_deg", spec.zones ? nlohmann::json{spec.zones->fov_h_deg, spec.zones->fov_v_deg} : nlohmann::json(nullptr)},
          {"zone_rays", spec.zones ? nlohmann::json(spec.zones->rays_per_zone) : nlohmann::json(nullptr)},
          {"targets", spec.zones ? nlohmann::json(spec.zones->targets) : nlohmann::json(nullptr)},
          {"target_separation_m", spec.zones ? nlohmann::json(spec.zones->target_separation_m) : nlohmann::json(nullptr)},
          {"target_order", spec.zones ? nlohmann::json(spec.zones->strongest_first ? "strongest" : "closest")
                                      : nlohmann::json(nullptr)},
          {"distance", spec.zones ? nlohmann::json(spec.zones->perpendicular ? "perpendicular" : "radial")
                                  : nlohmann::json(nullptr)}};
}

}  // namespace proxsim
