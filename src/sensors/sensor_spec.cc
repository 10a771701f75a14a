#include "sensors/sensor_spec.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sensors/distance_modes.h"
#include "sensors/multizone.h"
#include "sensors/noise_table.h"
#include "sensors/range_table.h"
#include "sensors/sensor_types.h"
#include "sensors/vl53l1x_settings.h"
#include "sensors/wave_speed.h"

namespace proxsim {

namespace {

// Two echoes of one ping are told apart when they arrive at least a pulse
// length apart: an ultrasonic burst of 8 cycles at 40 kHz (the HC-SR04
// datasheet's "8 cycle sonic burst") lasts 200 µs, c·τ/2 = 343 × 200e-6 / 2
// = 0.0343 m of range. An optical pulse has no such published figure: the
// optical types keep SensorSpec's default (ST's 600 mm).
constexpr double kUltrasonicEchoSeparation_m = kSpeedOfSoundInAir_m_s * (8.0 / 40000.0) / 2.0;

// ST's single-zone parts (VL53L0X, VL53L1X) report the mean time of the
// photons their SPADs count over the whole field of view, each surface
// counted by the light it returns: "the distance the sensor gives is a
// weighted average of all the objects seen in the field of view ... objects
// nearer to the sensor are going to reflect more light and get counted more
// heavily" (an ST engineer on the VL53L0X, ST community thread "Field of
// view of VL53L0X"); "the VL53L1X averages all the photon times it gets
// back" (the same, thread "VL53L1X unexplained distance change"). They do
// not tell two targets apart ("there is no way to determine if there are
// multiple objects within the field"; ST's multi-target parts, the VL53L3CX
// and the multi-zone ones, are histogram parts): the beam is one target, the
// separation SensorSpec's default +inf.
constexpr BeamReadout kStSingleZoneReadout = BeamReadout::kSignalWeighted;

// a multizone sensor's grid, and the grids its part has
void ValidateZones(const SensorSpec& spec, std::vector<std::string>& problems) {
  const auto fail = [&](const std::string& key, const std::string& expected, double got) {
    std::ostringstream message;
    message << key << ": expected " << expected << ", got " << got;
    problems.push_back(message.str());
  };
  if (spec.type != SensorType::kMultizone) {
    if (spec.zones) problems.push_back("zones: expected only with type multizone or a multi-zone part, got zones for a " +
                                       std::string(SensorTypeName(spec.type)) + " sensor");
    return;
  }
  if (!spec.zones) {
    problems.push_back("zones: expected [nx, ny] for a multizone sensor, got none");
    return;
  }
  const ZoneSpec& z = *spec.zones;
  if (spec.beam) problems.push_back("beam: expected no beam for a multizone sensor (its zones are its rays), got a beam");
  if (spec.noise.dropout != 0) fail("noise.dropout", "0 for a multizone sensor (its zones report their own status)", spec.noise.dropout);
  if (z.nx < 1 || z.nx > 64) fail("zones[0]", "a number of zones across in [1, 64]", z.nx);
  if (z.ny < 1 || z.ny > 64) fail("zones[1]", "a number of zones down in [1, 64]", z.ny);
  if (const MultizonePart* part = FindMultizonePart(spec.part); part != nullptr && MultizoneMaxRate_hz(spec) <= 0) {
    problems.push_back("zones: expected " + MultizonePartGrids(*part) + " for a " + spec.part + " (" + part->source +
                       "), got [" + std::to_string(z.nx) + ", " + std::to_string(z.ny) + "]");
  }
  const auto fov = [&](const char* key, double deg) {
    if (!std::isfinite(deg) || deg <= 0 || deg >= 170) fail(key, "a full field of view in (0, 170) degrees", deg);
  };
  fov("fov_deg[0]", z.fov_h_deg);
  fov("fov_deg[1]", z.fov_v_deg);
  const int k = static_cast<int>(std::lround(std::sqrt(std::max(z.rays_per_zone, 0))));
  if (z.rays_per_zone < 1 || z.rays_per_zone > 16 || k * k != z.rays_per_zone) {
    fail("zone_rays", "rays per zone k*k with k in [1, 4] (1, 4, 9 or 16)", z.rays_per_zone);
  }
  if (z.targets < 1 || z.targets > 4) fail("targets", "targets per zone in [1, 4] (ST's NB_TARGET_PER_ZONE)", z.targets);
  if (!std::isfinite(z.target_separation_m) || z.target_separation_m <= 0) {
    fail("target_separation_m", "a finite separation > 0 m", z.target_separation_m);
  }
}

// echoes other than the first: a time-of-flight beam, of a type (not a part) that reports several
void ValidateEchoes(const SensorSpec& spec, std::vector<std::string>& problems) {
  if (!std::isfinite(spec.echo_separation_m) || spec.echo_separation_m <= 0) {
    std::ostringstream message;
    message << "echo_separation_m: expected a finite separation > 0 m, got " << spec.echo_separation_m;
    problems.push_back(message.str());
  }
  if (spec.echoes == EchoSelection::kFirst) return;
  const std::string got = std::string(", got ") + EchoSelectionName(spec.echoes);
  if (!spec.single_echo_source.empty()) {
    problems.push_back("echoes: expected first for a " + spec.part + ", which reports one echo (" +
                       spec.single_echo_source + ")" + got);
  } else if (spec.type == SensorType::kMultizone) {
    problems.push_back("echoes: expected first for a multizone sensor (its zones report up to `targets` targets "
                       "each, in zones/; `target_order: strongest` puts the strongest first)" + got);
  } else if (!IsTimeOfFlight(spec.type)) {
    problems.push_back("echoes: expected first for a " + std::string(SensorTypeName(spec.type)) +
                       " sensor (only time-of-flight beams hear several echoes)" + got);
  } else if (!spec.beam || spec.beam->rays < 2) {
    problems.push_back("echoes: expected first for a sensor of one ray (one ray has one echo; give a beam of "
                       "several rays)" + got);
  }
}

}  // namespace

RateLimit PartRateLimit(const SensorSpec& spec) {
  if (const MultizonePart* part = FindMultizonePart(spec.part); part != nullptr && spec.zones) {
    return {MultizoneMaxRate_hz(spec), part->source};
  }
  return {spec.max_rate_hz, spec.max_rate_source};
}

// a type's name and family are its row in sensor_types.cc
const char* SensorTypeName(SensorType type) { return TraitsOf(type).name; }

std::optional<SensorType> SensorTypeFromName(std::string_view name) {
  for (const SensorTypeTraits& traits : AllSensorTypeTraits()) {
    if (name == traits.name) return traits.type;
  }
  return std::nullopt;
}

const std::vector<std::string>& SensorTypeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const SensorTypeTraits& traits : AllSensorTypeTraits()) all.emplace_back(traits.name);
    return all;
  }();
  return names;
}

bool IsTimeOfFlight(SensorType type) { return TraitsOf(type).time_of_flight; }

const char* NoiseModelName(NoiseModel model) {
  switch (model) {
    case NoiseModel::kMultiplicative: return "multiplicative";
    case NoiseModel::kAdditive: return "additive";
    case NoiseModel::kDistanceScaled: return "distance_scaled";
  }
  return "?";
}

std::optional<NoiseModel> NoiseModelFromName(std::string_view name) {
  for (NoiseModel model : {NoiseModel::kMultiplicative, NoiseModel::kAdditive, NoiseModel::kDistanceScaled}) {
    if (name == NoiseModelName(model)) return model;
  }
  return std::nullopt;
}

const char* EchoSelectionName(EchoSelection selection) {
  switch (selection) {
    case EchoSelection::kFirst: return "first";
    case EchoSelection::kStrongest: return "strongest";
    case EchoSelection::kAll: return "all";
  }
  return "?";
}

std::optional<EchoSelection> EchoSelectionFromName(std::string_view name) {
  for (EchoSelection selection : {EchoSelection::kFirst, EchoSelection::kStrongest, EchoSelection::kAll}) {
    if (name == EchoSelectionName(selection)) return selection;
  }
  return std::nullopt;
}

SensorSpec SensorSpec::Preset(SensorType type) {
  SensorSpec spec;
  spec.type = type;
  switch (type) {
    case SensorType::kIdeal:  // exact distances, for comparison (the paper's Fig. 8)
      spec.min_range_m = 0.0;
      spec.max_range_m = 2.0;
      spec.max_incidence_deg = 90.0;
      spec.noise = {0.0, 0.0};
      break;
    case SensorType::kLaser:  // §5 "A laser range finder"
      spec.min_range_m = 0.0;
      spec.max_range_m = 2.0;
      spec.max_incidence_deg = 45.0;
      spec.noise = {0.01, 0.0};
      break;
    case SensorType::kUltrasonic:  // §5 "An ultrasonic sensor"
      spec.min_range_m = 0.1;
      spec.max_range_m = 1.0;
      spec.max_incidence_deg = 15.0;
      spec.noise = {0.01, 0.0};
      spec.echo_separation_m = kUltrasonicEchoSeparation_m;
      break;
    case SensorType::kReflectance:  // §5 "A reflectance sensor"
      spec.min_range_m = 0.0;
      spec.max_range_m = 1.0;
      spec.max_incidence_deg = 90.0;
      spec.noise = {0.01, 0.0};
      break;
    case SensorType::kLookup:  // a datasheet sensor: the table is the scenario's
      spec.min_range_m = 0.0;
      spec.max_range_m = 2.0;
      spec.max_incidence_deg = 90.0;
      spec.noise = {0.0, 0.0};
      break;
    case SensorType::kMultizone:  // a generic grid of zones: 8x8 over 45° x 45°, no noise until given
      spec.min_range_m = 0.0;
      spec.max_range_m = 4.0;
      spec.max_incidence_deg = 90.0;
      spec.noise = {0.0, 0.0};
      spec.zones = ZoneSpec{};
      break;
  }
  return spec;
}

const std::vector<std::string>& SensorSpec::PartNames() {
  static const std::vector<std::string> names = {"hc_sr04", "sharp_gp2y0a21", "vl53l0x", "vl53l1x",
                                                      "vl53l4cx", "vl53l5cx", "vl53l7cx", "vl53l8cx"};
  return names;
}

std::optional<SensorSpec> SensorSpec::PartPreset(std::string_view name) {
  if (name == "hc_sr04") {
    // HC-SR04 ultrasonic ranging module (ElecFreaks / Cytron datasheet
    // "Ultrasonic Ranging Module HC-SR04"): 40 kHz, range 2 cm – 4 m,
    // "ranging accuracy can reach 3 mm". Its "measuring angle 15 degree" is a
    // nominal figure; published measurements show a lobe wide near the
    // sensor that narrows with distance. The reach rows are the Parallax
    // PING))) product guide's (28015, v2.0: same open 40 kHz transducer pair)
    // for a flat target kept normal to the axis — about 30° off the axis at
    // 12 in (0.305 m) narrowing to 10° at 45 in (1.143 m) — as G. Dyrkacz's
    // HC-SR04 beam tests (2020) report and confirm in shape on the HC-SR04
    // (wider close in, tightening beyond 40 cm). The cone is therefore 60°
    // wide and the rays far off the axis count only near the sensor. The
    // paper's 15° ultrasonic incidence window is kept; the lobe is uniform
    // within the reach.
    SensorSpec spec = Preset(SensorType::kUltrasonic);
    spec.part = "hc_sr04";
    spec.min_range_m = 0.02;
    spec.max_range_m = 4.0;
    spec.noise = {.sigma = 0.003, .mean = 0.0, .model = NoiseModel::kAdditive, .resolution_m = 0.003};
    spec.beam = BeamSpec{.aperture_deg = 60.0,
                         .rays = 91,
                         .pattern = BeamPattern::kUniform,
                         .width_deg = 10.0,
                         .table = {},
                         .reach = {{0.305, 30.0}, {1.143, 10.0}}};
    // "we suggest to use over 60ms measurement cycle, in order to prevent
    // trigger signal to the echo signal": at most 1/60 ms ≈ 16.7 Hz
    spec.max_rate_hz = 1.0 / 0.060;
    spec.max_rate_source = "HC-SR04 datasheet: \"we suggest to use over 60ms measurement cycle\"";
    // with no echo the module's echo line stays high 38 ms, then it gives up
    // (the module's documented timeout, e.g. buildcircuit.com's HC-SR04 page:
    // "If no obstacle is detected, the output pin will give a 38ms high level signal")
    spec.echo_timeout_s = 0.038;
    // the echo line goes low at the first echo: the module reports one
    spec.single_echo_source = "HC-SR04 datasheet: the echo pulse lasts until the first echo returns";
    return spec;
  }
  if (name == "sharp_gp2y0a21") {
    // Sharp GP2Y0A21YK0F analog IR distance sensor (Sharp datasheet
    // E4-A00201EN): distance measuring range 10–80 cm; output at L = 80 cm
    // 0.4 V typ. (0.25–0.55); output change from L = 80 cm to 10 cm 1.9 V
    // typ. (so 2.3 V at 10 cm); the "analog output voltage vs distance to
    // reflective object" curve rises to about 3.1 V near 6–7 cm and falls
    // below that (the non-monotonic branch: a near object reads like a far
    // one). Between 10 and 80 cm the rows follow V ≈ 20.99/L[cm] + 0.19, a
    // fit to that curve, pinned to the datasheet's 2.3 V and 0.4 V; the rows
    // under 10 cm are read approximately off the curve. The noise fraction
    // (2 %) is not in the datasheet; it is an assumption. Beyond the table the
    // output stays at its last value (Webots' lookupTable convention).
    SensorSpec spec = Preset(SensorType::kLookup);
    spec.part = "sharp_gp2y0a21";
    spec.min_range_m = 0.10;
    spec.max_range_m = 0.80;
    spec.lookup_table = {{0.00, 0.00, 0.02}, {0.02, 1.60, 0.02}, {0.04, 2.75, 0.02}, {0.06, 3.10, 0.02},
                         {0.08, 2.75, 0.02}, {0.10, 2.30, 0.02}, {0.15, 1.59, 0.02}, {0.20, 1.24, 0.02},
                         {0.25, 1.03, 0.02}, {0.30, 0.89, 0.02}, {0.40, 0.71, 0.02}, {0.50, 0.61, 0.02},
                         {0.60, 0.54, 0.02}, {0.70, 0.47, 0.02}, {0.80, 0.40, 0.02}};
    return spec;
  }
  if (name == "vl53l0x") {
    // ST VL53L0X time-of-flight laser ranging sensor (ST datasheet DocID029104):
    // 940 nm VCSEL, "up to 2 m" (long-range mode), field of view 25°, ranging
    // output in millimetres, ranging accuracy about ±3 % indoors on a white
    // target (taken here as σ = 3 % of the distance, the paper's law). The
    // range by target and light is Table 11's "typical" column (33 ms timing
    // budget, full field of view): white 88 % 200 cm indoor (long range
    // profile), 80 cm outdoor overcast; grey 17 % 80 cm indoor, 50 cm outdoor;
    // "outdoor overcast" is ST's 10 kcps/SPAD, "equivalent to 5 kLux daylight".
    SensorSpec spec = Preset(SensorType::kLaser);
    spec.part = "vl53l0x";
    spec.min_range_m = 0.03;
    spec.max_range_m = 2.0;
    spec.range_table = {{0.88, 0.0, 2.0}, {0.17, 0.0, 0.8}, {0.88, 5.0, 0.8}, {0.17, 5.0, 0.5}};
    spec.noise = {.sigma = 0.03, .mean = 0.0, .model = NoiseModel::kMultiplicative, .resolution_m = 0.001};
    // the ranging error by target and light, Table 12 (standard deviation,
    // 33 ms timing budget): white 4 % (at 120 cm) and grey 7 % (at 70 cm)
    // indoors, 7 % (60 cm) and 12 % (40 cm) outdoors overcast; it replaces
    // the 3 % above, which stays the σ a scenario's own noise.sigma replaces
    spec.sigma_table = {{0.88, 0.0, 0.04}, {0.17, 0.0, 0.07}, {0.88, 5.0, 0.07}, {0.17, 5.0, 0.12}};
    spec.beam = BeamSpec{.aperture_deg = 25.0, .rays = 19, .pattern = BeamPattern::kUniform, .width_deg = 10.0, .table = {}, .reach = {}};
    spec.single_echo_source = "VL53L0X datasheet DocID029104: one ranging result per measurement";
    spec.beam_readout = kStSingleZoneReadout;
    return spec;
  }
  if (name == "vl53l1x") {
    // ST VL53L1X time-of-flight ranging sensor (datasheet DocID031281 Rev 3):
    // 940 nm VCSEL, receiver field of view "programmable from 15 to 27
    // degrees" (diagonal; the full 16x16 SPAD array, taken here as a 27°
    // cone), minimum ranging distance 4 cm, millimetre output. Its three
    // distance modes carry the range and error tables (distance_modes.cc);
    // long is the default. Its region of interest (16x16 SPADs, the full
    // array) and timing budget (100 ms, at which the tables hold) narrow the
    // cone, scale the ranges and bound the rate (vl53l1x_settings.h).
    SensorSpec spec = Preset(SensorType::kLaser);
    spec.part = "vl53l1x";
    spec.min_range_m = 0.04;
    spec.noise = {.sigma = 0.020, .mean = 0.0, .model = NoiseModel::kAdditive, .resolution_m = 0.001};
    spec.beam = BeamSpec{.aperture_deg = 27.0, .rays = 19, .pattern = BeamPattern::kUniform, .width_deg = 10.0, .table = {}, .reach = {}};
    spec.roi_spads = {kVl53l1xFullRoi, kVl53l1xFullRoi};
    spec.timing_budget_ms = kVl53l1xDefaultBudget_ms;
    ApplyDistanceMode(*FindDistanceMode("vl53l1x", DefaultDistanceMode("vl53l1x")), spec);
    spec.single_echo_source = "VL53L1X datasheet DocID031281: one ranging result per measurement";
    spec.beam_readout = kStSingleZoneReadout;
    return spec;
  }
  if (const MultizonePart* part = FindMultizonePart(std::string(name))) {
    // ST's multi-zone parts and the single-zone, multi-target VL53L4CX
    // (multizone.cc cites the figures): the part's first grid of zones over
    // its square field of view, ranging from 2 cm to its longest range, with
    // its datasheet's range tables (inner and corner zones) and ranging
    // accuracy at its resolution where they were found. σ = 3 % of the
    // distance stays the σ a scenario's own noise.sigma replaces, and the
    // VL53L4CX's σ (no accuracy table found for it); 1 mm steps (the drivers
    // report millimetres) and the 2 cm minimum are assumptions.
    SensorSpec spec = Preset(SensorType::kMultizone);
    spec.part = part->name;
    spec.min_range_m = 0.02;
    spec.max_range_m = part->max_range_m;
    spec.noise = {.sigma = 0.03, .mean = 0.0, .model = NoiseModel::kMultiplicative, .resolution_m = 0.001};
    const int across = part->grids_across[0];
    spec.zones = ZoneSpec{.nx = across, .ny = across, .fov_h_deg = part->fov_deg, .fov_v_deg = part->fov_deg,
                          .rays_per_zone = part->rays_per_zone, .targets = part->targets, .target_separation_m = 0.6,
                          .perpendicular = part->perpendicular};
    ApplyMultizonePartTables(spec);
    return spec;
  }
  return std::nullopt;
}

std::vector<std::string> SensorSpec::Validate() const {
  std::vector<std::string> problems;
  auto fail = [&](const std::string& key, const std::string& expected, double got) {
    std::ostringstream message;
    message << key << ": expected " << expected << ", got " << got;
    problems.push_back(message.str());
  };
  auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(min_range_m) || min_range_m < 0) fail("range_m[0]", "a finite minimum range >= 0 m", min_range_m);
  if (!finite(max_range_m) || max_range_m <= 0) fail("range_m[1]", "a finite maximum range > 0 m", max_range_m);
  if (finite(min_range_m) && finite(max_range_m) && max_range_m <= min_range_m) {
    fail("range_m", "[min, max] with min < max (max given)", max_range_m);
  }
  if (!finite(max_incidence_deg) || max_incidence_deg < 0 || max_incidence_deg > 90) {
    fail("max_incidence_deg", "an angle in [0, 90] degrees", max_incidence_deg);
  }
  if (!finite(noise.sigma) || noise.sigma < 0) fail("noise.sigma", "a finite standard deviation >= 0", noise.sigma);
  if (!finite(noise.mean)) fail("noise.mean", "a finite mean", noise.mean);
  if (!finite(noise.resolution_m) || noise.resolution_m < 0) {
    fail("noise.resolution_m", "a finite resolution >= 0 m", noise.resolution_m);
  }
  if (!finite(noise.dropout) || noise.dropout < 0 || noise.dropout > 1) {
    fail("noise.dropout", "a probability in [0, 1]", noise.dropout);
  }
  if (noise.model == NoiseModel::kDistanceScaled && !IsTimeOfFlight(type)) {
    problems.push_back("noise.model: expected multiplicative or additive for a " + std::string(SensorTypeName(type)) +
                       " sensor (distance_scaled applies to time-of-flight distances), got distance_scaled");
  }
  if (!finite(echo_threshold) || echo_threshold < 0 || echo_threshold > 1) {
    fail("echo_threshold", "a relative echo strength in [0, 1]", echo_threshold);
  }
  if (!finite(specular_exponent) || specular_exponent <= 0) {
    fail("specular_exponent", "a finite exponent > 0", specular_exponent);
  }
  if (echo_model == EchoModel::kPhysical && !IsTimeOfFlight(type)) {
    problems.push_back("echo_model: expected window for a " + std::string(SensorTypeName(type)) +
                       " sensor (physical applies to ideal, laser and ultrasonic), got physical");
  }
  if (beam && type == SensorType::kLookup) {
    problems.push_back("beam: expected no beam for a lookup sensor (its table already is the whole sensor), got a beam");
  }
  if (beam) {
    if (!finite(beam->aperture_deg) || beam->aperture_deg <= 0 || beam->aperture_deg >= 180) {
      fail("beam.aperture_deg", "a full cone angle in (0, 180) degrees", beam->aperture_deg);
    }
    if (beam->rays < 1 || beam->rays > 1000) fail("beam.rays", "a number of rays in [1, 1000]", beam->rays);
    if (beam->pattern == BeamPattern::kGaussian && (!finite(beam->width_deg) || beam->width_deg <= 0)) {
      fail("beam.pattern.gaussian.width_deg", "a finite width > 0 degrees", beam->width_deg);
    }
    if (beam->pattern == BeamPattern::kTable) {
      double max_gain = 0;
      if (beam->table.size() < 2) fail("beam.pattern.table", "at least 2 rows [angle_deg, gain]", static_cast<double>(beam->table.size()));
      for (std::size_t i = 0; i < beam->table.size(); ++i) {
        const auto& [angle, gain] = beam->table[i];
        const std::string row = "beam.pattern.table[" + std::to_string(i) + "]";
        if (!finite(angle) || angle < 0 || angle > 180 || (i > 0 && !(angle > beam->table[i - 1][0]))) {
          fail(row + "[0]", "angles in [0, 180] degrees, strictly ascending", angle);
        }
        if (!finite(gain) || gain < 0) fail(row + "[1]", "a finite gain >= 0", gain);
        if (finite(gain)) max_gain = std::max(max_gain, gain);
      }
      if (beam->table.size() >= 2 && !(max_gain > 0)) fail("beam.pattern.table", "at least one gain > 0", max_gain);
    }
    if (!beam->reach.empty() && !IsTimeOfFlight(type)) {
      problems.push_back("beam.reach: expected only for a time-of-flight sensor (an echo heard off the axis by "
                         "distance), got it for a " + std::string(SensorTypeName(type)) + " sensor");
    }
    for (std::size_t i = 0; i < beam->reach.size(); ++i) {
      const auto& [d_m, half_angle_deg] = beam->reach[i];
      const std::string row = "beam.reach[" + std::to_string(i) + "]";
      if (!finite(d_m) || d_m < 0 || (i > 0 && !(d_m > beam->reach[i - 1][0]))) {
        fail(row + "[0]", "distances >= 0 m, strictly ascending", d_m);
      }
      if (!finite(half_angle_deg) || half_angle_deg < 0 || half_angle_deg > 90) {
        fail(row + "[1]", "a half-angle in [0, 90] degrees", half_angle_deg);
      }
    }
  }
  if (!finite(echo_timeout_s) || echo_timeout_s < 0) fail("echo_timeout_s", "a finite time >= 0 s", echo_timeout_s);
  if (echo_timeout_s > 0 && type != SensorType::kUltrasonic) {
    problems.push_back("echo_timeout_s: expected only for an ultrasonic sensor, got it for a " +
                       std::string(SensorTypeName(type)) + " sensor");
  }
  if (type == SensorType::kLookup) {
    if (lookup_table.size() < 2) {
      fail("lookup_table", "at least 2 rows [distance_m, output, noise_fraction]", static_cast<double>(lookup_table.size()));
    }
    for (std::size_t i = 0; i < lookup_table.size(); ++i) {
      const LookupRow& row = lookup_table[i];
      const std::string key = "lookup_table[" + std::to_string(i) + "]";
      if (!finite(row.distance_m) || row.distance_m < 0 || (i > 0 && !(row.distance_m > lookup_table[i - 1].distance_m))) {
        fail(key + "[0]", "distances >= 0 m, strictly ascending", row.distance_m);
      }
      if (!finite(row.output)) fail(key + "[1]", "a finite output", row.output);
      if (!finite(row.noise_fraction) || row.noise_fraction < 0) fail(key + "[2]", "a noise fraction >= 0", row.noise_fraction);
    }
  } else if (!lookup_table.empty()) {
    problems.push_back("lookup_table: expected only with type lookup, got a table for a " +
                       std::string(SensorTypeName(type)) + " sensor");
  }
  ValidateEchoes(*this, problems);
  ValidateZones(*this, problems);
  ValidateRangeTable(*this, problems);
  ValidateSigmaTable(*this, problems);
  ValidateVl53l1xSettings(*this, problems);
  return problems;
}

}  // namespace proxsim
