// What generated worlds share: the families' names, the validation of a
// configuration, the draws within a range, and the dispatch to a kind.
#include "scene/world_generator.h"

#include <cmath>
#include <cstdio>

#include "scene/person.h"
#include "scene/world_generator_internal.h"

namespace proxsim {

namespace {
// A room's counts, each bounded: every piece placed on the walk's way
// searches the whole floor for the way through again (a 100 x 100 m room at
// 200 of each and 50 blockers per 5 m took 9 minutes).
constexpr int kMaxRoomPieces = 50;
constexpr int kMaxBlockersPer5m = 10;
constexpr const char* kRoomCountReason = " (each piece may search the whole floor for the way through; docs/trust.md)";
}  // namespace

const std::vector<std::string>& CourseFamilyNames() {
  static const std::vector<std::string> names = {"stairs_up", "stairs_down", "hole", "pit",
                                                 "gap",       "step",        "boxes", "ramp"};
  return names;
}

namespace gen {

double Round_m(double value) { return std::round(value * 1000.0) / 1000.0; }

double Draw(const GenRange& range, double difficulty, KeyedRandom& random) {
  return range.easy + difficulty * (range.hard - range.easy) * random.Uniform();
}

Vec2 UniformDirection(KeyedRandom& random) {
  for (;;) {
    const double x = random.Uniform(-1, 1), y = random.Uniform(-1, 1);
    const double r2 = x * x + y * y;
    // inside the unit disc (uniform in angle), away from its centre (where rounding would bias it)
    if (r2 <= 1 && r2 >= 1e-4) return Vec2(x / std::sqrt(r2), y / std::sqrt(r2));
  }
}

GenObject Box(std::string name, const Vec3& min_W, const Vec3& max_W, bool ground, double albedo) {
  GenObject object;
  object.name = std::move(name);
  object.kind = GenObject::Kind::kBox;
  for (int k = 0; k < 3; ++k) {
    object.size_m[k] = Round_m(max_W[k] - min_W[k]);
    object.xyz_m[k] = Round_m(0.5 * (min_W[k] + max_W[k]));
  }
  object.ground = ground;
  object.albedo = albedo;
  return object;
}

}  // namespace gen

std::vector<std::string> GenerateProblems(const GenerateConfig& config) {
  std::vector<std::string> problems;
  char text[240];
  const auto range_problem = [&](const char* key, const GenRange& range, double min, bool min_exclusive,
                                 const char* expected) {
    for (const double value : {range.easy, range.hard}) {
      if (std::isfinite(value) && (min_exclusive ? value > min : value >= min)) continue;
      std::snprintf(text, sizeof text, "%s: [%g, %g]: expected %s", key, range.easy, range.hard, expected);
      problems.emplace_back(text);
      return;
    }
  };
  if (!(config.difficulty >= 0 && config.difficulty <= 1)) problems.push_back("difficulty: expected a number in [0, 1]");
  if (config.kind == GenerateConfig::Kind::kCourse) {
    const CourseConfig& c = config.course;
    if (!(c.length_m >= 2 && c.length_m <= 1000)) problems.push_back("length_m: expected a length in [2, 1000] m");
    if (!(c.width_m >= 0.5 && c.width_m <= 100)) problems.push_back("width_m: expected a width in [0.5, 100] m");
    range_problem("stairs.rise_m", c.stairs_rise_m, 0, true, "rises > 0 m");
    char foot[64];
    std::snprintf(foot, sizeof foot, "treads at least a foot long (%.2f m)", kFootLength_m);
    range_problem("stairs.tread_m", c.stairs_tread_m, kFootLength_m, false, foot);
    range_problem("stairs.steps", c.stairs_steps, 1, false, "at least 1 step");
    range_problem("hole.width_m", c.hole_width_m, 0, true, "widths > 0 m");
    range_problem("hole.depth_m", c.hole_depth_m, 0, true, "depths > 0 m (a hole goes down)");
    range_problem("pit.width_m", c.pit_width_m, kFootLength_m, false, "widths a foot long at least (a pit is stepped into)");
    range_problem("pit.depth_m", c.pit_depth_m, 0, true, "depths > 0 m (a pit goes down)");
    range_problem("gap.width_m", c.gap_width_m, 0, true, "widths > 0 m");
    range_problem("step.height_m", c.step_height_m, 0, true, "heights > 0 m");
    range_problem("boxes.height_m", c.boxes_height_m, 0, true, "heights > 0 m");
    range_problem("ramp.slope_deg", c.ramp_slope_deg, 0, true, "slopes > 0 deg");
    range_problem("flat_m", c.flat_m, kFootLength_m, false, "flats a foot long at least");
    for (const GenRange& depth : {c.hole_depth_m, c.pit_depth_m}) {
      if (std::max(depth.easy, depth.hard) > gen::kCourseSlab_m - 0.1) {
        std::snprintf(text, sizeof text, "hole.depth_m, pit.depth_m: at most %.1f m", gen::kCourseSlab_m - 0.1);
        problems.emplace_back(text);
        break;
      }
    }
    if (std::max(c.ramp_slope_deg.easy, c.ramp_slope_deg.hard) > 45) problems.push_back("ramp.slope_deg: at most 45 deg");
  } else {
    const RoomConfig& r = config.room;
    if (!(r.size_m.minCoeff() >= 3 && r.size_m.maxCoeff() <= 100)) problems.push_back("size_m: expected [x, y], each in [3, 100] m");
    if (!(r.height_m > 0 && r.height_m <= 20)) problems.push_back("height_m: expected a height in (0, 20] m");
    if (!(r.robot_width_m > 0 && r.robot_width_m < 2)) problems.push_back("robot_width_m: expected a width in (0, 2) m");
    if (!(r.margin_m >= 0 && r.margin_m < 2)) problems.push_back("margin_m: expected a margin in [0, 2) m");
    // the corridor must fit between the start and the walls a metre away
    if (!(r.robot_width_m + r.margin_m <= 1.4)) problems.push_back("robot_width_m + margin_m: at most 1.4 m");
    for (const auto& [key, range] : {std::pair{"tables", r.tables}, {"chairs", r.chairs}, {"shelves", r.shelves},
                                     {"clutter", r.clutter}, {"people", r.people}}) {
      range_problem(key, range, 0, false, "counts >= 0");
      if (std::max(range.easy, range.hard) > kMaxRoomPieces)
        problems.push_back(std::string(key) + ": at most " + std::to_string(kMaxRoomPieces) + kRoomCountReason);
    }
    range_problem("blockers.count", r.blockers, 0, false, "counts >= 0");
    if (std::max(r.blockers.easy, r.blockers.hard) > kMaxBlockersPer5m)
      problems.push_back("blockers.count: at most " + std::to_string(kMaxBlockersPer5m) + " per 5 m" + kRoomCountReason);
    range_problem("blockers.width_m", r.blocker_width_m, 0.02, false, "widths of 0.02 m at least");
    range_problem("blockers.height_m", r.blocker_height_m, 0.02, false, "heights of 0.02 m at least");
    if (std::max(r.blocker_width_m.easy, r.blocker_width_m.hard) > 2) problems.push_back("blockers.width_m: at most 2 m");
    if (std::max(r.blocker_height_m.easy, r.blocker_height_m.hard) > r.height_m)
      problems.push_back("blockers.height_m: at most the room's height");
    char heights[64];
    std::snprintf(heights, sizeof heights, "heights in [%g, %g] m", kPersonMinHeight_m, kPersonMaxHeight_m);
    range_problem("people_height_m", r.person_height_m, kPersonMinHeight_m, false, heights);
    const double tallest_m = std::max(r.person_height_m.easy, r.person_height_m.hard);
    if (tallest_m > kPersonMaxHeight_m) problems.push_back(std::string("people_height_m: expected ") + heights);
    if (tallest_m >= r.height_m) {
      std::snprintf(text, sizeof text, "people_height_m: a person %g m tall does not fit in a room %g m high", tallest_m,
                    r.height_m);
      problems.emplace_back(text);
    }
    range_problem("people_speed_m_s", r.person_speed_m_s, 0, true, "speeds > 0 m/s");
  }
  return problems;
}

GeneratedWorld GenerateWorld(const GenerateConfig& config) {
  // the user's seed mixed with the kind and the difficulty (to the
  // millionth): seed k of a room at 0.3 and at 0.6 are two rooms, not one
  // room drawn twice with more furniture
  GenerateConfig mixed = config;
  const auto micro = static_cast<std::uint64_t>(std::llround(config.difficulty * 1e6));
  mixed.seed = KeyedRandom::MixSeed(config.seed, static_cast<std::uint64_t>(config.kind), micro);
  return mixed.kind == GenerateConfig::Kind::kCourse ? gen::GenerateCourse(mixed) : gen::GenerateRoom(mixed);
}

}  // namespace proxsim
