#include "sensors/sensor_model.h"

#include <algorithm>

#include "core/enum_names.h"
#include "sensors/beam_echoes.h"
#include "sensors/echo_groups.h"
#include "sensors/noise_table.h"
#include "sensors/range_table.h"

namespace proxsim {

namespace {
constexpr EnumNameTable<ReadingStatus, 8> kStatusNames = {{
    {ReadingStatus::kOk, "ok"},
    {ReadingStatus::kNoEcho, "no_echo"},
    {ReadingStatus::kTooClose, "too_close"},
    {ReadingStatus::kGrazing, "grazing"},
    {ReadingStatus::kSelf, "self"},
    {ReadingStatus::kDropout, "dropout"},
    {ReadingStatus::kNotSampled, "not_sampled"},
    {ReadingStatus::kCrosstalk, "crosstalk"},
}};
static_assert(InCodeOrder(kStatusNames));
}  // namespace

const char* ReadingStatusName(ReadingStatus status) { return NameIn(kStatusNames, status); }

const std::vector<std::string>& ReadingStatusNames() {
  static const std::vector<std::string> names = NamesIn(kStatusNames);
  return names;
}

double IncidenceDeg(double dir_x, double dir_y, double dir_z, double normal_x, double normal_y,
                    double normal_z) {
  // Two-sided surfaces: the normal's sign does not matter.
  const double cos_alpha = std::abs(dir_x * normal_x + dir_y * normal_y + dir_z * normal_z);
  return RadToDeg(std::acos(std::min(cos_alpha, 1.0)));
}

double LookupOutput(const std::vector<LookupRow>& table, double distance_m, double* noise_fraction) {
  const auto set_fraction = [&](double f) {
    if (noise_fraction) *noise_fraction = f;
  };
  if (table.empty()) {
    set_fraction(0.0);
    return 0.0;
  }
  // out of the table: its first or last row (a miss, d = +inf, is beyond it)
  if (!(distance_m > table.front().distance_m)) {
    set_fraction(table.front().noise_fraction);
    return table.front().output;
  }
  if (!(distance_m < table.back().distance_m)) {
    set_fraction(table.back().noise_fraction);
    return table.back().output;
  }
  const auto upper = std::upper_bound(table.begin(), table.end(), distance_m,
                                      [](double d, const LookupRow& row) { return d < row.distance_m; });
  const LookupRow& b = *upper;
  const LookupRow& a = *(upper - 1);
  const double u = (distance_m - a.distance_m) / (b.distance_m - a.distance_m);
  set_fraction(a.noise_fraction + u * (b.noise_fraction - a.noise_fraction));
  return a.output + u * (b.output - a.output);
}

double LookupDistance(const std::vector<LookupRow>& table, double output) {
  if (table.empty()) return 0.0;
  // the farthest segment whose outputs bracket the value
  for (std::size_t i = table.size() - 1; i > 0; --i) {
    const LookupRow& a = table[i - 1];
    const LookupRow& b = table[i];
    const double lo = std::min(a.output, b.output);
    const double hi = std::max(a.output, b.output);
    if (output >= lo && output <= hi) {
      if (a.output == b.output) return b.distance_m;
      return a.distance_m + (output - a.output) / (b.output - a.output) * (b.distance_m - a.distance_m);
    }
  }
  // outside every segment (noise beyond the curve's extremes): the closest row, the farthest on ties
  std::size_t best = table.size() - 1;
  for (std::size_t i = table.size(); i-- > 0;) {
    if (std::abs(table[i].output - output) < std::abs(table[best].output - output)) best = i;
  }
  return table[best].distance_m;
}

double FlightTimeShift(const Vec3& p_WS, const Vec3& v_W, const Vec3& p_WH, double d_m, double c_m_s) {
  // fixed-point iteration from the static round trip; it contracts by |v|/c,
  // so a few steps reach the last bit (the cap guards against |v| near c)
  double tau_s = 2.0 * d_m / c_m_s;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double next_s = (d_m + (p_WH - (p_WS + v_W * tau_s)).norm()) / c_m_s;
    const bool converged = std::abs(next_s - tau_s) <= 1e-16 * next_s;
    tau_s = next_s;
    if (converged) break;
  }
  return 0.5 * c_m_s * tau_s - d_m;
}

double MovingSurfaceMeeting_m(double d_m, const Vec3& dir_W, const Vec3& n_W, const Vec3& v_W, double c_m_s) {
  const double n_dir = n_W.dot(dir_W);
  if (n_dir == 0) return d_m;
  const double factor = 1.0 - n_W.dot(v_W) / (c_m_s * n_dir);
  // a surface receding at the wave's own speed is never met: keep the static distance
  return factor > 0 ? d_m / factor : d_m;
}

double PhysicalEchoEnergy(const SensorSpec& spec, const Echo& echo) {
  const double alpha = DegToRad(echo.incidence_deg);
  const double r = spec.type == SensorType::kUltrasonic ? echo.acoustic_reflectivity : echo.ir_albedo;
  const double s = echo.specular;
  const double lobe = std::max(0.0, std::cos(2.0 * alpha));
  return r * ((1.0 - s) * std::cos(alpha) + s * std::pow(lobe, spec.specular_exponent));
}

double ReturnedEnergy(const SensorSpec& spec, const Echo& echo) {
  if (spec.echo_model == EchoModel::kPhysical) return PhysicalEchoEnergy(spec, echo);
  return spec.type == SensorType::kUltrasonic ? echo.acoustic_reflectivity : echo.ir_albedo;
}

double IncidentReflectance(const SensorSpec& spec, const Echo& echo, double off_axis_deg) {
  Echo facing = echo;
  facing.incidence_deg = off_axis_deg;
  const double facing_energy = PhysicalEchoEnergy(spec, facing);
  return facing_energy > 0 ? echo.ir_albedo * PhysicalEchoEnergy(spec, echo) / facing_energy : 0.0;
}

ReadingStatus EchoStatus(const SensorSpec& spec, const Echo& echo, double gain) {
  // an optical part's range shrinks with a darker target (one met at a
  // grazing angle is darker: IncidentReflectance) and brighter light (range_table.h)
  const bool by_target = !spec.range_table.empty() && echo.distance_m <= spec.max_range_m;
  return EchoStatusWithin(spec, echo, gain,
                          by_target ? ReflectanceMaxRange_m(spec, IncidentReflectance(spec, echo))
                                    : std::numeric_limits<double>::infinity());
}

ReadingStatus EchoStatusWithin(const SensorSpec& spec, const Echo& echo, double gain, double target_range_m) {
  // the range windows of §4.1
  if (!(echo.distance_m <= spec.max_range_m)) return ReadingStatus::kNoEcho;
  if (!(echo.distance_m <= target_range_m)) return ReadingStatus::kNoEcho;
  if (echo.distance_m < spec.min_range_m) return ReadingStatus::kTooClose;
  // the returned energy, or the paper's incidence window of §4.2 and the beam's threshold
  if (spec.echo_model == EchoModel::kPhysical && IsTimeOfFlight(spec.type)) {
    if (!(gain * PhysicalEchoEnergy(spec, echo) >= spec.echo_threshold)) return ReadingStatus::kGrazing;
  } else {
    if (echo.incidence_deg > spec.max_incidence_deg) return ReadingStatus::kGrazing;
    if (gain < 1.0 && gain < spec.echo_threshold) return ReadingStatus::kNoEcho;
  }
  return echo.from_robot ? ReadingStatus::kSelf : ReadingStatus::kOk;
}

namespace {

Reading NoDetection(const SensorSpec& spec, ReadingStatus status, double distance_m = std::numeric_limits<double>::infinity()) {
  Reading reading;
  reading.status = status;
  reading.d_m = spec.max_range_m;
  reading.signal = spec.type == SensorType::kReflectance ? 0.0 : std::numeric_limits<double>::quiet_NaN();
  // a lookup sensor always outputs something: the table at the true distance (its last row on a miss)
  if (spec.type == SensorType::kLookup) reading.output = LookupOutput(spec.lookup_table, distance_m);
  return reading;
}

// d_r rounded to the sensor's resolution, if it has one
double Quantise(const NoiseSpec& noise, double d_m) {
  return noise.resolution_m > 0 ? std::round(d_m / noise.resolution_m) * noise.resolution_m : d_m;
}

}  // namespace

double TimeOfFlightReading_m(const NoiseSpec& noise_spec, double d, double gaussian_g) {
  const double noise = noise_spec.sigma * gaussian_g + noise_spec.mean;
  double d_m = d;
  switch (noise_spec.model) {
    case NoiseModel::kMultiplicative: d_m = d * (1.0 + noise); break;
    case NoiseModel::kAdditive: d_m = d + noise; break;
    case NoiseModel::kDistanceScaled: d_m = d + noise * d * d; break;
  }
  return Quantise(noise_spec, d_m);
}

namespace {

// Eq. (1)'s noise-free signal, scaled by the IR albedo when the sensor uses materials
double ReflectanceSignal(const SensorSpec& spec, const Echo& echo) {
  const double d = echo.distance_m;
  const double cos_alpha = std::cos(DegToRad(echo.incidence_deg));
  if (d <= 0.0) return std::numeric_limits<double>::infinity();
  double signal = (spec.max_range_m - d) / (d * d) * cos_alpha * cos_alpha;
  if (spec.use_material) signal *= echo.ir_albedo;
  return signal;
}

// the noisy signal from the noise-free one, inverted to d_r (§5)
Reading InvertReflectance(const SensorSpec& spec, double clean_signal, double noise, ReadingStatus status) {
  const double d_max = spec.max_range_m;
  Reading reading;
  if (std::isinf(clean_signal)) {
    // a surface touching the emitter: infinite signal, the inversion's limit is 0
    reading.signal = clean_signal;
    reading.d_m = 0.0;
  } else {
    reading.signal = spec.noise.model == NoiseModel::kAdditive ? clean_signal + noise : clean_signal * (1.0 + noise);
    // s ≤ 0 (at d_max, at 90°, or noise ≤ −1): no light comes back
    if (!(reading.signal > 0.0)) return NoDetection(spec, ReadingStatus::kNoEcho);
    // the positive root of s·d² + d − d_max = 0, in a form without cancellation
    reading.d_m = Quantise(spec.noise, 2.0 * d_max / (1.0 + std::sqrt(1.0 + 4.0 * reading.signal * d_max)));
  }
  reading.status = status;
  return reading;
}

// a reading from an echo that counts (status kOk or kSelf)
Reading MeasureCounted(const SensorSpec& spec, const Echo& echo, ReadingStatus status, const NoiseDraw& draw) {
  if (draw.uniform <= spec.noise.dropout) return NoDetection(spec, ReadingStatus::kDropout, echo.distance_m);

  // the Gaussian law of §4.3
  const double noise = spec.noise.sigma * draw.gaussian_g + spec.noise.mean;

  if (spec.type == SensorType::kReflectance) return InvertReflectance(spec, ReflectanceSignal(spec, echo), noise, status);

  Reading reading;
  reading.status = status;
  if (spec.type == SensorType::kLookup) {
    // Webots' lookupTable: σ = fraction·output, then the distance it implies
    double fraction = 0;
    const double output = LookupOutput(spec.lookup_table, echo.distance_m, &fraction);
    reading.output = output + fraction * output * draw.gaussian_g;
    reading.d_m = Quantise(spec.noise, LookupDistance(spec.lookup_table, reading.output));
    return reading;
  }

  // time of flight (laser, ultrasonic) and the ideal sensor: d_r = d·(1 + N), or a variant
  // σ by the target's reflectance and the light, where the datasheet tabulates it (noise_table.h)
  const NoiseSpec noise_spec = spec.sigma_table.empty() ? spec.noise : NoiseAt(spec, echo.ir_albedo);
  reading.d_m = TimeOfFlightReading_m(noise_spec, echo.distance_m + echo.flight_shift_m, draw.gaussian_g);
  return reading;
}

bool Counts(ReadingStatus status) { return status == ReadingStatus::kOk || status == ReadingStatus::kSelf; }

}  // namespace

Reading Measure(const SensorSpec& spec, const Echo& echo, double gaussian_g, double dropout_uniform) {
  return Measure(spec, echo, [&](int) { return NoiseDraw{gaussian_g, dropout_uniform}; });
}

Reading Measure(const SensorSpec& spec, const Echo& echo, const DrawOfRay& draw) {
  const ReadingStatus status = EchoStatus(spec, echo, 1.0);
  if (!Counts(status)) return NoDetection(spec, status, echo.distance_m);
  return MeasureCounted(spec, echo, status, draw(0));
}

BeamReading MeasureBeam(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                        std::span<const NoiseDraw> draws) {
  return MeasureBeam(spec, echoes, rays, [&](int ray) { return draws[static_cast<std::size_t>(ray)]; });
}

BeamReading MeasureBeam(const SensorSpec& spec, std::span<const Echo> echoes, std::span<const BeamRay> rays,
                        const DrawOfRay& draw) {
  BeamReading out;
  const std::size_t n = echoes.size();

  // why nothing counted: the nearest hit within range says it
  const auto no_detection = [&]() {
    int nearest = -1;
    for (std::size_t i = 0; i < n; ++i) {
      if (echoes[i].distance_m <= spec.max_range_m && BeamReaches(spec.beam, rays[i].off_axis_deg, echoes[i].distance_m) &&
          (nearest < 0 || echoes[i].distance_m < echoes[nearest].distance_m)) {
        nearest = static_cast<int>(i);
      }
    }
    out.truth_ray = std::max(nearest, 0);
    out.ray = -1;
    const ReadingStatus status = nearest < 0 ? ReadingStatus::kNoEcho : EchoStatus(spec, echoes[nearest], rays[nearest].gain);
    out.reading = NoDetection(spec, Counts(status) ? ReadingStatus::kNoEcho : status);
    return out;
  };

  if (spec.type == SensorType::kReflectance) {
    // an IR spot: the weighted sum of the rays' signals, one noise draw, one inversion
    double sum = 0.0;
    double largest = -1.0;
    int dominant = -1;
    ReadingStatus dominant_status = ReadingStatus::kNoEcho;
    for (std::size_t i = 0; i < n; ++i) {
      const ReadingStatus status = EchoStatus(spec, echoes[i], 1.0);
      if (!Counts(status)) continue;
      const double contribution = rays[i].weight * ReflectanceSignal(spec, echoes[i]);
      sum += contribution;
      if (contribution > largest) {
        largest = contribution;
        dominant = static_cast<int>(i);
        dominant_status = status;
      }
    }
    if (dominant < 0 || !(sum > 0.0)) return no_detection();
    // one draw for the spot (ray 0's key), as when every ray's draws were made
    const NoiseDraw spot_draw = draw(0);
    if (spot_draw.uniform <= spec.noise.dropout) {
      out.reading = NoDetection(spec, ReadingStatus::kDropout);
      out.truth_ray = dominant;
      return out;
    }
    const double noise = spec.noise.sigma * spot_draw.gaussian_g + spec.noise.mean;
    out.reading = InvertReflectance(spec, sum, noise, dominant_status);
    out.truth_ray = dominant;
    out.ray = out.reading.status == ReadingStatus::kNoEcho ? -1 : dominant;
    return out;
  }

  if (spec.beam_readout == BeamReadout::kSignalWeighted) {
    // a part that weighs its returns (ST's single-zone parts): each ray that
    // is heard and counts carries w·E/d² (w its weight in the pattern, E the
    // surface's returned energy, ρ·cos θ for a matte one, d its arrival),
    // resolved into targets as a zone resolves its own (echo_groups.h); the
    // nearest is read at its signal-weighted centre, with the noise of its
    // nearest ray's draw. The robot's own body makes no target (as in a
    // zone); when only it counts, the reading is its nearest echo's, `self`.
    thread_local std::vector<RangedRay> counted;
    thread_local std::vector<ResolvedTarget> targets;
    counted.clear();
    int nearest_self = -1;
    for (std::size_t i = 0; i < n; ++i) {
      if (!BeamReaches(spec.beam, rays[i].off_axis_deg, echoes[i].distance_m)) continue;
      const ReadingStatus status = EchoStatus(spec, echoes[i], rays[i].gain);
      if (!Counts(status)) continue;
      const double arrival_m = echoes[i].distance_m + echoes[i].flight_shift_m;
      if (status == ReadingStatus::kSelf) {
        if (nearest_self < 0 || arrival_m < echoes[nearest_self].distance_m + echoes[nearest_self].flight_shift_m)
          nearest_self = static_cast<int>(i);
        continue;
      }
      // (a surface at the emitter returns without bound: it is the reading)
      counted.push_back({arrival_m, static_cast<int>(i),
                         arrival_m > 0 ? rays[i].weight * PhysicalEchoEnergy(spec, echoes[i]) / (arrival_m * arrival_m)
                                       : std::numeric_limits<double>::infinity()});
    }
    if (counted.empty() && nearest_self < 0) return no_detection();
    Echo read = echoes[std::max(nearest_self, 0)];
    int nearest = nearest_self;
    ReadingStatus status = ReadingStatus::kSelf;
    if (!counted.empty()) {
      ResolveTargets(counted, spec.beam_target_separation_m, 1, targets);
      nearest = counted[targets.front().rays.begin].ray;
      read = echoes[static_cast<std::size_t>(nearest)];
      read.distance_m = targets.front().d_m;
      read.flight_shift_m = 0.0;  // the centre is of the arrivals
      status = ReadingStatus::kOk;
    }
    out.reading = MeasureCounted(spec, read, status, draw(nearest));
    out.truth_ray = nearest;
    out.ray = out.reading.status == ReadingStatus::kDropout ? -1 : nearest;
    return out;
  }

  // time of flight: the first echo back among those that count
  int first = -1;
  ReadingStatus first_status = ReadingStatus::kNoEcho;
  for (std::size_t i = 0; i < n; ++i) {
    const double arrival = echoes[i].distance_m + echoes[i].flight_shift_m;
    if (first >= 0 && !(arrival < echoes[first].distance_m + echoes[first].flight_shift_m)) continue;
    if (!BeamReaches(spec.beam, rays[i].off_axis_deg, echoes[i].distance_m)) continue;
    const ReadingStatus status = EchoStatus(spec, echoes[i], rays[i].gain);
    if (!Counts(status)) continue;
    first = static_cast<int>(i);
    first_status = status;
  }
  if (first < 0) return no_detection();
  if (spec.echoes == EchoSelection::kStrongest) {
    // the echo whose rays return the most (beam_echoes.h), reported from its nearest ray
    first = StrongestEchoRay(spec, echoes, rays);
    first_status = EchoStatus(spec, echoes[first], rays[first].gain);
  }
  out.reading = MeasureCounted(spec, echoes[first], first_status, draw(first));
  out.truth_ray = first;
  out.ray = out.reading.status == ReadingStatus::kDropout ? -1 : first;
  return out;
}

}  // namespace proxsim
