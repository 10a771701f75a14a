#include "sensors/beam_echoes.h"

#include <limits>

#include "sensors/echo_groups.h"
#include "sensors/noise_table.h"

namespace proxsim {

std::vector<BeamEcho> BeamEchoes(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                                 int max_echoes) {
  std::vector<RangedRay> heard;
  for (std::size_t i = 0; i < echoes.size(); ++i) {
    if (!BeamReaches(spec.beam, rays[i].off_axis_deg, echoes[i].distance_m)) continue;
    const ReadingStatus status = EchoStatus(spec, echoes[i], rays[i].gain);
    if (status != ReadingStatus::kOk && status != ReadingStatus::kSelf) continue;
    heard.push_back({echoes[i].distance_m + echoes[i].flight_shift_m, static_cast<int>(i)});
  }
  std::vector<EchoGroup> groups;
  SplitEchoes(heard, spec.echo_separation_m, max_echoes, groups);
  std::vector<BeamEcho> out;
  out.reserve(groups.size());
  for (const EchoGroup& group : groups) {
    BeamEcho echo{.d_m = heard[group.begin].d_m, .signal = 0.0, .ray = heard[group.begin].ray, .truth_d_m = heard[group.begin].d_m};
    for (std::size_t k = group.begin; k < group.end; ++k) {
      const auto ray = static_cast<std::size_t>(heard[k].ray);
      echo.signal += rays[ray].weight * ReturnedEnergy(spec, echoes[ray]);
    }
    out.push_back(echo);
  }
  return out;
}

int StrongestEchoRay(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays) {
  int ray = -1;
  double strongest = -std::numeric_limits<double>::infinity();
  for (const BeamEcho& echo : BeamEchoes(spec, echoes, rays, std::numeric_limits<int>::max())) {
    if (echo.signal > strongest) {  // nearest first: a tie keeps the nearer
      strongest = echo.signal;
      ray = echo.ray;
    }
  }
  return ray;
}

std::vector<BeamEcho> ReportedEchoes(const SensorSpec& spec, std::span<const Echo> echoes,
                                     std::span<const BeamRay> rays, const DrawOfRay& draw) {
  std::vector<BeamEcho> reported;
  for (BeamEcho echo : BeamEchoes(spec, echoes, rays, kMaxEchoes)) {
    const NoiseDraw noise_draw = draw(echo.ray);
    if (noise_draw.uniform <= spec.noise.dropout) continue;
    const NoiseSpec noise = NoiseAt(spec, echoes[static_cast<std::size_t>(echo.ray)].ir_albedo);
    echo.d_m = TimeOfFlightReading_m(noise, echo.d_m, noise_draw.gaussian_g);
    reported.push_back(echo);
  }
  return reported;
}

}  // namespace proxsim
