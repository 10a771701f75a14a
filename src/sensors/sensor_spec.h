// The parameters of a proximity sensor (paper §5), as a plain struct with the
// paper's three sensors and an ideal one as named presets, plus the sensor
// physics beyond the paper (docs/sensors.md), every part of it off by default: a beam
// of several rays with a pattern, materials, a physical echo model, a lookup
// table, noise variants. Presets for three real parts cite their datasheets in
// sensor_spec.cc. Every value may be overridden per sensor in the scenario
// file; Validate() lists every violated condition at once.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace proxsim {

/// The physics a sensor follows. ideal, laser and ultrasonic are time of
/// flight; reflectance follows Eq. (1); lookup maps distance to an output
/// through a datasheet table.
/// multizone is time of flight over a grid of zones (multizone.h).
enum class SensorType { kIdeal, kLaser, kUltrasonic, kReflectance, kLookup, kMultizone };

/// "ideal", "laser", "ultrasonic", "reflectance", "lookup" or "multizone".
const char* SensorTypeName(SensorType type);
/// The type named `name`, or nullopt.
std::optional<SensorType> SensorTypeFromName(std::string_view name);
/// Every type name, for messages.
const std::vector<std::string>& SensorTypeNames();
/// True for ideal, laser, ultrasonic and multizone: the reading is a time of flight.
bool IsTimeOfFlight(SensorType type);

/// How N is applied (N = σ·G + m, G a standard normal draw).
enum class NoiseModel {
  kMultiplicative,  ///< the paper's §4.3: x·(1 + N); σ dimensionless
  kAdditive,        ///< x + N; σ in the unit of x (m for distances, signal units for reflectance)
  kDistanceScaled,  ///< d + N·d²/(1 m); σ in 1/m — triangulation-like error growing with d² (distances only)
};
const char* NoiseModelName(NoiseModel model);
std::optional<NoiseModel> NoiseModelFromName(std::string_view name);

/// Gaussian noise N = σ·G + m of paper §4.3 and its variants.
struct NoiseSpec {
  double sigma = 0.0;  ///< standard deviation σ, >= 0 (unit: see NoiseModel)
  double mean = 0.0;   ///< mean m, same unit as σ
  NoiseModel model = NoiseModel::kMultiplicative;
  double resolution_m = 0.0;  ///< > 0: d_r rounded to a multiple of this; 0: no quantisation
  double dropout = 0.0;       ///< probability in [0, 1] that a detection is lost (status `dropout`)
};

/// How the beam's gain varies with the angle θ off the sensor's axis.
enum class BeamPattern {
  kUniform,   ///< g(θ) = 1
  kGaussian,  ///< g(θ) = exp(−θ²/(2·w²)), w = width_deg
  kTable,     ///< piecewise linear in θ through [angle_deg, gain] rows, relative to the table's largest gain
};

/// A cone of rays around the sensor's +x axis (beam.h lays them out).
struct BeamSpec {
  double aperture_deg = 0.0;  ///< full cone angle, in (0, 180)
  int rays = 1;               ///< number of rays, in [1, 1000]; 1 is the axis ray alone
  BeamPattern pattern = BeamPattern::kUniform;
  double width_deg = 10.0;    ///< the gaussian's w, > 0
  std::vector<std::array<double, 2>> table;  ///< [angle_deg, gain] rows, angles ascending
  /// How far off the axis an echo is still heard, by distance: [d_m,
  /// half_angle_deg] rows, distances ascending, piecewise linear and held
  /// beyond the ends (an ultrasonic lobe narrows with distance); empty: the
  /// whole cone at every distance (beam.h's BeamReaches).
  std::vector<std::array<double, 2>> reach;
};

/// How a time-of-flight echo is judged to come back.
enum class EchoModel {
  kWindow,    ///< the paper's: incidence α <= α*, nothing else
  kPhysical,  ///< returned energy r·((1−s)·cos α + s·max(0, cos 2α)^n) >= echo_threshold (Phong-like, as HELIOS++)
};

/// One row of a datasheet table: at distance_m the sensor outputs `output`,
/// with a Gaussian noise of σ = noise_fraction·output (Webots' lookupTable).
struct LookupRow {
  double distance_m = 0.0;
  double output = 0.0;
  double noise_fraction = 0.0;
};

/// A multi-zone time-of-flight sensor's grid of zones (multizone.h).
struct ZoneSpec {
  int nx = 8;                  ///< zones across (the sensor's y), [1, 64]
  int ny = 8;                  ///< zones down (its z), [1, 64]
  double fov_h_deg = 45.0;     ///< full field of view across, (0, 170) degrees
  double fov_v_deg = 45.0;     ///< full field of view down, (0, 170) degrees
  int rays_per_zone = 4;       ///< rays sampling each zone: k² for k in [1, 4]
  int targets = 1;             ///< targets reported per zone, [1, 4]
  double target_separation_m = 0.6;  ///< surfaces closer in range than this merge into one target, > 0
  /// The order of a zone's targets, as ST's ULD sets it (vl53l5cx_set_target_order):
  /// false: closest first; true: strongest first (the most signal), which is
  /// the ULD's own default — kept off here so that a zone reports what it
  /// always did unless asked (docs/sensors.md#multi-zone-time-of-flight).
  bool strongest_first = false;
  /// The distance a zone reports: true, the perpendicular distance (projected
  /// on the sensor's axis, as ST's chips report it: "the radial to
  /// perpendicular conversion is done on the chip", an ST engineer on ST's
  /// community forum); false, the radial one along the zone's rays. The ST
  /// parts' presets set it; `distance: perpendicular | radial` in a scenario.
  bool perpendicular = false;
};

/// Which echoes of a ping a time-of-flight beam reports (docs/sensors.md#several-echoes).
enum class EchoSelection {
  kFirst,      ///< the nearest echo that counts (the paper's reading; the default)
  kStrongest,  ///< the echo whose rays return the most signal
  kAll,        ///< the reading is the first; up to kMaxEchoes echoes, nearest first, beside it
};
/// "first", "strongest" or "all".
const char* EchoSelectionName(EchoSelection selection);
std::optional<EchoSelection> EchoSelectionFromName(std::string_view name);
/// The most echoes a reading keeps with `echoes: all`.
inline constexpr int kMaxEchoes = 4;

/// How a time-of-flight beam of several rays turns its rays' returns into
/// its reading (docs/sensors.md#what-a-beam-reports).
enum class BeamReadout {
  /// The first echo back among the rays that count: a receiver that stops
  /// its clock at the first echo over its threshold (a sonar; the paper's
  /// models and every generic type).
  kFirstEcho,
  /// The rays' returns weighed by the signal each carries (the ray's weight
  /// in the pattern, the surface's returned energy, 1/d²) and resolved into
  /// targets at `beam_target_separation_m`, the nearest reported at its
  /// signal-weighted centre, as a multi-zone zone resolves its own
  /// (echo_groups.h): ST's single-zone time-of-flight parts.
  kSignalWeighted,
};

struct SensorSpec {
  SensorType type = SensorType::kIdeal;
  std::string part;                  ///< the named part this came from ("" for the paper's presets)
  double min_range_m = 0.0;          ///< d_min: closer hits are `too_close`; >= 0
  double max_range_m = 2.0;          ///< d_max: farther hits are `no_echo`; > d_min
  double max_incidence_deg = 90.0;   ///< α*: hits at larger incidence are `grazing`; in [0, 90]
  NoiseSpec noise;

  /// A cone of rays; nullopt: the paper's single ray along +x.
  std::optional<BeamSpec> beam;
  /// A ray of pattern gain g counts for a time-of-flight beam only if
  /// g·(echo strength) >= echo_threshold (strength 1 in the window model); in [0, 1].
  double echo_threshold = 0.1;
  EchoModel echo_model = EchoModel::kWindow;
  double specular_exponent = 20.0;   ///< n of the physical model's specular lobe, > 0
  /// Reflectance: scale Eq. (1)'s s by the surface's IR albedo. Off by
  /// default, so the paper's formula holds whatever the scene's materials.
  bool use_material = false;
  /// type lookup: rows by ascending distance; at least 2.
  std::vector<LookupRow> lookup_table;
  /// type multizone: its grid of zones (required for that type, refused for the others).
  std::optional<ZoneSpec> zones;
  /// An optical time-of-flight part's longest range by the target's
  /// reflectance and the ambient light, as its datasheet tabulates it:
  /// rows [reflectance in (0, 1], ambient_klux >= 0, max_range_m > 0]
  /// (range_table.h); empty: the range does not depend on them.
  std::vector<std::array<double, 3>> range_table;
  /// A multi-zone sensor's corner zones' longest range, rows as range_table's
  /// (its datasheet tabulates the inner and the corner zones apart); a zone
  /// between them reads between the two by its place in the grid
  /// (multizone.h ZoneCornerWeight). Empty: every zone reads range_table.
  std::vector<std::array<double, 3>> corner_range_table;
  /// The scene's ambient light, klux (scene.ambient_klux, set when the scenario loads).
  double ambient_klux = 0.0;
  /// A part's shortest measurement cycle as a rate, Hz (0: none), and where it
  /// comes from; a multi-zone part's depends on its zones (PartRateLimit).
  double max_rate_hz = 0.0;
  std::string max_rate_source;
  /// Ultrasonic: how long the receiver listens after its ping, s (0: until
  /// the next ping). An echo of any ping arriving later is not heard; the
  /// window in which other sensors' pings are heard (crosstalk).
  double echo_timeout_s = 0.0;

  /// Which echoes a time-of-flight beam reports, and the range difference
  /// below which two surfaces' echoes merge into one (m, > 0): for optical
  /// beams ST's 600 mm minimum separation of two targets (UM2884), the only
  /// multi-target optical figure we have; ultrasonic presets set their pulse's.
  EchoSelection echoes = EchoSelection::kFirst;
  double echo_separation_m = 0.6;
  /// A named part that reports one echo per ping refuses `echoes` other than
  /// first: why (its datasheet), "" for a type that may report several.
  std::string single_echo_source;
  /// How a beam of several rays makes its reading (a single ray is the
  /// paper's model whatever this says); the part presets set it.
  BeamReadout beam_readout = BeamReadout::kFirstEcho;
  /// kSignalWeighted: returns closer in range than this merge into one
  /// target (m, > 0); +inf, every return one target — the VL53L0X and
  /// VL53L1X time every photon they count into one mean (sensor_spec.cc).
  double beam_target_separation_m = std::numeric_limits<double>::infinity();
  /// A part's distance mode ("short", "medium", "long" for the VL53L1X), "" for none.
  std::string distance_mode;
  /// The VL53L1X's region of interest on its 16x16 SPAD array, [width, height]
  /// in SPADs (each in [4, 16]), and its timing budget, ms; both 0 for a part
  /// without them (vl53l1x_settings.h says what they change).
  std::array<int, 2> roi_spads = {0, 0};
  double timing_budget_ms = 0.0;
  /// The ranging error by target and light, as the datasheet tabulates it:
  /// rows [reflectance in (0, 1], ambient_klux >= 0, sigma >= 0], σ in the
  /// noise model's unit; interpolated as range_table's rows (noise_table.h).
  /// Empty: noise.sigma at any target and light.
  std::vector<std::array<double, 3>> sigma_table;

  /// The paper's values for a type (§5; the ideal sensor: [0, 2] m, 90°, no
  /// noise; lookup: an empty table, to be given).
  static SensorSpec Preset(SensorType type);

  /// A named real part ("hc_sr04", "sharp_gp2y0a21", "vl53l0x", "vl53l1x", "vl53l4cx", "vl53l5cx",
  /// "vl53l7cx", "vl53l8cx"), or nullopt.
  static std::optional<SensorSpec> PartPreset(std::string_view name);
  /// Every part name, for messages.
  static const std::vector<std::string>& PartNames();

  /// Every violated condition, one message each, worded after the scenario key; empty if valid.
  std::vector<std::string> Validate() const;
};

/// The fastest rate a part may sample at, and the source of the figure
/// (max_hz 0: no limit): the part's measurement cycle, or a multi-zone part's
/// ranging frequency at its resolution.
struct RateLimit {
  double max_hz = 0.0;
  std::string source;
};
RateLimit PartRateLimit(const SensorSpec& spec);

}  // namespace proxsim
