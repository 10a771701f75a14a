#include "sensors/sensor_keys.h"

#include <algorithm>

namespace proxsim {

const std::vector<SensorKey>& SensorKeys() {
  static const std::vector<SensorKey> keys = {
    {"name", "text", "required",
     "unique among the sensors; names its rows in the outputs"},
    {"type", "see above", "required",
     "the preset"},
    {"link", "a link name or `world`", "`world`",
     "what the sensor is fixed to; a link requires a `robot` (an unknown link is refused, with the robot's links listed)"},
    {"pose", "`{xyz_m, rpy_deg}`", "the link's frame",
     "the sensor frame in its link's frame; the beam is its +x axis"},
    {"see_robot", "bool", "true",
     "false: the robot's own links are transparent to this sensor"},
    {"range_m", "`[min, max]`, m", "preset",
     "0 ≤ min < max: nearer hits are `too_close`, nothing within max is `no_echo`"},
    {"max_incidence_deg", "[0, 90], degrees", "preset",
     "hits at a larger incidence are `grazing`"},
    {"noise.model", R"(`multiplicative` \| `additive` \| `distance_scaled`)", "`multiplicative`",
     "how N = σG + m is applied: d(1 + N), d + N, d + N·d² (the last for time of flight only)"},
    {"noise.sigma", "≥ 0", "preset",
     "σ (unit: see the model; dimensionless for the paper's multiplicative noise)"},
    {"noise.mean", "number", "preset",
     "m, same unit as σ"},
    {"noise.sigma_table", "`[[reflectance, ambient_klux, sigma], ...]`", "`vl53l0x`, `vl53l1x`, the ST multi-zone parts (by `zones`): their datasheets'; otherwise none",
     "laser and multizone only: σ by the target's IR albedo and `scene.ambient_klux` (the datasheet's ranging error), interpolated as docs/sensors.md says; a `noise.sigma` without a table turns a part's off"},
    {"noise.resolution_m", "≥ 0, m", "0",
     "the reported distance is rounded to a multiple of this; 0: no rounding"},
    {"noise.dropout", "[0, 1]", "0",
     "probability that a detection is lost (status `dropout`)"},
    {"beam.aperture_deg", "(0, 180), degrees", "required in `beam`",
     "the full cone angle"},
    {"beam.rays", "[1, 1000]", "1",
     "rays in the cone (1: the axis alone)"},
    {"beam.pattern", R"(`uniform` \| `{gaussian: {width_deg}}` \| `{table: [[angle_deg, gain], ...]}`)", "`uniform`",
     "the gain g(θ) of a ray θ off the axis"},
    {"beam.reach", "`[[d_m, half_angle_deg], ...]`", "none (`hc_sr04`: its published lobe)",
     "time of flight only: an echo from d_m away is heard only from rays at most this far off the axis (piecewise linear, held beyond the ends): a lobe that narrows with distance"},
    {"echo_model", R"(`window` \| `physical`)", "`window`",
     "time of flight only: the paper's incidence window, or a returned energy against `echo_threshold`"},
    {"echo_threshold", "[0, 1]", "0.1",
     "a ray counts only if g(θ)·(echo strength) reaches it"},
    {"specular_exponent", "> 0", "20",
     "n of the physical echo's specular lobe"},
    {"use_material", "bool", "false",
     "reflectance only: scale the signal by the surface's IR albedo"},
    {"lookup_table", "`[[distance_m, output, noise_fraction], ...]`", "—",
     "`type: lookup` only: at least 2 rows, distances strictly ascending; the range defaults to the table's"},
    {"zones", "`[nx, ny]`, each in [1, 64]", "8x8 (`multizone`, the ST multi-zone parts), 1x1 (`vl53l4cx`)",
     "`multizone` and the ST parts only: the field of view's grid of zones; a VL53L5CX/L7CX/L8CX has `[4, 4]` or `[8, 8]`, a VL53L4CX `[1, 1]`"},
    {"fov_deg", "`[h, v]`, each in (0, 170), degrees", "45 x 45 (L5CX, L8CX), 60 x 60 (L7CX), 18 x 18 (L4CX)",
     "`multizone` only: the full square field of view across (the sensor's y) and down (its z)"},
    {"zone_rays", "1, 4, 9 or 16", "4 (`vl53l4cx`: 16)",
     "rays sampling each zone (a k x k grid in its cell)"},
    {"targets", "[1, 4]", "1 (`vl53l4cx`: 4)",
     "targets reported per zone, in `target_order` (ST's NB_TARGET_PER_ZONE; the VL53L4CX driver's VL53L4CX_MAX_RANGE_RESULTS)"},
    {"target_separation_m", "> 0, m", "0.6",
     "surfaces closer in range than this merge into one target (ST: 600 mm)"},
    {"target_order", R"(`closest` \| `strongest`)", "`closest`",
     "`multizone` and the ST parts only: a zone's targets nearest first, or the one returning the most signal first (ST's two target orders; its driver's default is `strongest`)"},
    {"distance", R"(`perpendicular` \| `radial`)", "`perpendicular` (the ST multi-zone parts), `radial` (`multizone`, `vl53l4cx`)",
     "`multizone` and the ST parts only: a zone's distance projected on the sensor's axis, as ST's chips report it (a flat wall facing the sensor reads the same in every zone), or along the zone's rays"},
    {"range_table", "`[[reflectance, ambient_klux, max_range_m], ...]`", "`vl53l0x`, `vl53l1x` (by `distance_mode`, `roi`, `timing_budget_ms`), the ST multi-zone parts (by `zones`, their inner zones'): their datasheets'; otherwise none",
     "laser and multizone only: the longest range by the target's IR albedo and `scene.ambient_klux`, interpolated as docs/sensors.md says; `[]` turns a part's off"},
    {"corner_range_table", "`[[reflectance, ambient_klux, max_range_m], ...]`", "the ST multi-zone parts (by `zones`): their datasheets' corner zones'; otherwise none",
     "multizone only: the corner zones' longest range; a zone between the centre and a corner reads between `range_table` and this by its distance from the grid's centre; `[]` turns a part's off"},
    {"distance_mode", R"(`short` \| `medium` \| `long`)", "`long` (`vl53l1x`)",
     "`vl53l1x` only: the part's distance mode, which sets its range, `range_table` and `noise.sigma_table` from its datasheet"},
    {"roi", "`[w, h]`, SPADs, each in [4, 16]", "`[16, 16]` (`vl53l1x`)",
     "`vl53l1x` only: the region of interest on its 16x16 SPAD array; a smaller one narrows the cone (15° at 4x4, 20° at 8x8, 27° at 16x16) and shortens the range (datasheet Table 9)"},
    {"timing_budget_ms", "ms: 20–1000 (short mode), 33–1000 (medium, long)", "100 (`vl53l1x`)",
     "`vl53l1x` only: the time of one ranging; scales the medium and long modes' ranges and bounds `rate_hz` to 1000 / budget"},
    {"echoes", R"(`first` \| `strongest` \| `all`)", "`first`",
     "time-of-flight beams of several rays only (not the single-echo parts): the reading is the nearest echo, or the one whose rays return the most signal; `all` also writes up to 4 echoes, nearest first, to `echoes/`"},
    {"echo_separation_m", "> 0, m", "0.0343 (ultrasonic: 8 cycles at 40 kHz), 0.6 (optical)",
     "echoes of one ping closer in range than this merge into one (`echoes: strongest \\| all`)"},
    {"rate_hz", "> 0, Hz", "every sample; a part with a measurement cycle: its limit",
     "the sensor reads at the first run sample of each of its own periods; a part refuses a rate above its datasheet's limit (`hc_sr04`: 16.7 Hz, its 60 ms cycle; `vl53l1x`: 1000 / `timing_budget_ms` Hz, 10 Hz at its default 100 ms; ST multi-zone parts: 60 Hz at 4x4, 15 Hz at 8x8; `vl53l4cx`: 30 Hz)"},
    {"latency_s", "0–10, s", "0",
     "a reading is reported, and seen by a strategy, this much later"},
    {"flight_time", "bool", "false",
     "time of flight only: the echo is received where the moving sensor is when it returns"},
    {"wave_speed_m_s", "> 0, m/s", "343 (ultrasonic), 299 792 458 (others)",
     "the wave speed for `flight_time` and crosstalk"},
    {"echo_timeout_s", "≥ 0, s", "0 (`hc_sr04`: 0.038)",
     "ultrasonic only: how long the receiver listens after its ping (0: until its next ping); later echoes are not heard"},
    {"fire", R"(`simultaneous` \| `round_robin` \| offset, s)", "`simultaneous`",
     "when the sensor pings within its period: at t = 0 + k/rate_hz, in an even slot among the `round_robin` sensors (file order), or this offset in [0, 1/rate_hz); needs `rate_hz` unless simultaneous"},
    {"crosstalk", "bool", "true",
     "ultrasonic only: the sensor hears other ultrasonic sensors' pings that reach it within its listening window (status `crosstalk`)"},
  };
  return keys;
}

std::vector<std::string> SensorKeyNames(const std::string& parent) {
  std::vector<std::string> names;
  const std::string prefix = parent.empty() ? "" : parent + ".";
  for (const SensorKey& key : SensorKeys()) {
    const std::string path = key.path;
    if (!path.starts_with(prefix)) continue;
    const std::string rest = path.substr(prefix.size());
    const std::string name = rest.substr(0, rest.find('.'));
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

std::string SensorKeysMarkdown() {
  std::string table = "| key | type, unit | default | meaning |\n|---|---|---|---|\n";
  for (const SensorKey& key : SensorKeys()) {
    table += "| `" + std::string(key.path) + "` | " + key.type_unit + " | " + key.default_text + " | " + key.meaning + " |\n";
  }
  return table;
}

}  // namespace proxsim
