// The course: sub-terrains walked along +x, each from a family (stairs up and
// down, holes, pits, gaps, single steps, fields of boxes, ramps) with flat
// ground between them, as Isaac Lab's terrain generator lays out its
// sub-terrains for legged robots, here in a line. The ground is slabs
// kCourseSlab_m thick under their tops, spanning the course's width; a hole
// or a gap is the space between two slabs (a hole has a bottom that is not
// ground, a gap none). The robot starts at the origin on `floor_0` and its
// path runs along the course's middle to its end.
#include <algorithm>
#include <cmath>

#include "scene/portable_trig.h"
#include "scene/world_generator_internal.h"

namespace proxsim::gen {

namespace {

constexpr double kGroundAlbedo = 0.5, kHoleAlbedo = 0.3, kBoxAlbedo = 0.6;

class CourseBuilder {
 public:
  CourseBuilder(const CourseConfig& course, double difficulty, GeneratedWorld& world)
      : c_(course), d_(difficulty), world_(world), half_width_(0.5 * course.width_m) {}

  double x() const { return x_; }
  double level() const { return level_; }

  /// Ground from x to x + length at height `top` (the level afterwards).
  void Ground(const std::string& name, double length_m, double top_m) {
    const double x1 = Round_m(x_ + length_m);
    world_.objects.push_back(
        Box(name, Vec3(x_, -half_width_, top_m - kCourseSlab_m), Vec3(x1, half_width_, top_m), true, kGroundAlbedo));
    x_ = x1;
    level_ = top_m;
  }

  void Flat(const std::string& name, KeyedRandom& random) { Ground(name, Round_m(Draw(c_.flat_m, d_, random)), level_); }

  void Element(CourseFamily family, int index, KeyedRandom& random) {
    const std::string name = CourseFamilyNames()[static_cast<int>(family)] + "_" + std::to_string(index);
    switch (family) {
      case CourseFamily::kStairsUp:
      case CourseFamily::kStairsDown: {
        const double sign = family == CourseFamily::kStairsUp ? 1 : -1;
        const int steps = static_cast<int>(std::lround(Draw(c_.stairs_steps, d_, random)));
        const double rise = Round_m(Draw(c_.stairs_rise_m, d_, random));
        const double tread = Round_m(Draw(c_.stairs_tread_m, d_, random));
        for (int k = 1; k <= steps; ++k) Ground(name + "_step_" + std::to_string(k), tread, Round_m(level_ + sign * rise));
        break;
      }
      case CourseFamily::kHole: {
        const double width = Round_m(Draw(c_.hole_width_m, d_, random));
        const double depth = Round_m(Draw(c_.hole_depth_m, d_, random));
        // the bottom, a 0.1 m slab that is not ground: the walls are the neighbours' sides
        world_.objects.push_back(Box(name, Vec3(x_, -half_width_, level_ - depth - 0.1),
                                     Vec3(Round_m(x_ + width), half_width_, level_ - depth), false, kHoleAlbedo));
        x_ = Round_m(x_ + width);
        break;
      }
      case CourseFamily::kPit: {
        const double width = Round_m(Draw(c_.pit_width_m, d_, random));
        const double depth = Round_m(Draw(c_.pit_depth_m, d_, random));
        const double level = level_;
        Ground(name, width, Round_m(level - depth));
        level_ = level;
        break;
      }
      case CourseFamily::kGap:
        x_ = Round_m(x_ + Draw(c_.gap_width_m, d_, random));
        break;
      case CourseFamily::kStep: {
        // up from the lowest levels, else either way
        const double height = Round_m(Draw(c_.step_height_m, d_, random));
        const double sign = level_ <= 0 || random.Uniform() < 0.5 ? 1 : -1;
        Ground(name, Round_m(Draw(c_.flat_m, d_, random)), Round_m(level_ + sign * height));
        break;
      }
      case CourseFamily::kBoxes: {
        // tiles of 0.4 m (a foot and a half), each at its own height over the level
        constexpr double kTile_m = 0.4;
        const int along = random.Integer(4, 6);
        const int across = std::max(1, static_cast<int>(std::floor(c_.width_m / kTile_m)));
        const double tile_y = c_.width_m / across;
        const double level = level_;
        for (int i = 0; i < along; ++i) {
          for (int j = 0; j < across; ++j) {
            const double top = Round_m(level + Draw(c_.boxes_height_m, d_, random));
            const double y0 = Round_m(-half_width_ + j * tile_y), y1 = Round_m(-half_width_ + (j + 1) * tile_y);
            world_.objects.push_back(Box(name + "_box_" + std::to_string(i * across + j + 1),
                                         Vec3(x_ + i * kTile_m, y0, top - kCourseSlab_m),
                                         Vec3(x_ + (i + 1) * kTile_m, y1, top), true, kBoxAlbedo));
          }
        }
        x_ = Round_m(x_ + along * kTile_m);
        break;
      }
      case CourseFamily::kRamp: {
        // 1.5 m of slope, up from the lowest levels, else either way; a slab pitched about y
        constexpr double kRun_m = 1.5, kThickness_m = 0.2;
        const double slope_deg = std::round(10 * Draw(c_.ramp_slope_deg, d_, random)) / 10;
        const double sign = level_ <= 0 || random.Uniform() < 0.5 ? 1 : -1;
        // sin, cos and sqrt of our own, not libm's (portable_trig.h): the same bits on every CPU;
        // the slab is pitched by the drawn slope, its run's rise rounded to the millimetre
        const double s = DegToRad(slope_deg);
        const double rise = Round_m(sign * kRun_m * PortableSin(s) / PortableCos(s));
        GenObject ramp;
        ramp.name = name;
        ramp.kind = GenObject::Kind::kBox;
        ramp.size_m = Vec3(Round_m(std::sqrt(kRun_m * kRun_m + rise * rise)), c_.width_m, kThickness_m);
        // the top face's middle at (x + run/2, level + rise/2); its normal (sin p, 0, cos p) for the pitch p about y
        ramp.rpy_deg = Vec3(0, -sign * slope_deg, 0);
        const double pitch = DegToRad(ramp.rpy_deg.y());
        const Vec3 normal(PortableSin(pitch), 0, PortableCos(pitch));
        const Vec3 centre = Vec3(x_ + 0.5 * kRun_m, 0, level_ + 0.5 * rise) - 0.5 * kThickness_m * normal;
        ramp.xyz_m = Vec3(Round_m(centre.x()), 0, Round_m(centre.z()));
        ramp.ground = true;
        ramp.albedo = kGroundAlbedo;
        world_.objects.push_back(ramp);
        x_ = Round_m(x_ + kRun_m);
        level_ = Round_m(level_ + rise);
        break;
      }
    }
  }

 private:
  const CourseConfig& c_;
  double d_;
  GeneratedWorld& world_;
  double half_width_;
  double x_ = -1.0;
  double level_ = 0;
};

}  // namespace

GeneratedWorld GenerateCourse(const GenerateConfig& config) {
  const CourseConfig& course = config.course;
  GeneratedWorld world;
  CourseBuilder builder(course, config.difficulty, world);

  // the families in their order: as listed, or every one shuffled by the seed
  std::vector<CourseFamily> order = course.elements;
  if (order.empty()) {
    for (int f = 0; f < static_cast<int>(CourseFamilyNames().size()); ++f) order.push_back(static_cast<CourseFamily>(f));
    KeyedRandom shuffle(config.seed, 0);
    for (std::size_t i = order.size(); i-- > 1;) std::swap(order[i], order[shuffle.Integer(0, static_cast<int>(i))]);
  }

  // the start: 2 m of floor around the origin, then element after element,
  // each followed by flat ground, while there is room for one more
  builder.Ground("floor_0", 2.0, 0.0);
  std::vector<int> family_count(CourseFamilyNames().size(), 0);
  constexpr double kRoomForAnElement_m = 3.0;
  for (int element = 0; builder.x() + kRoomForAnElement_m < course.length_m; ++element) {
    KeyedRandom random(config.seed, 1000 + static_cast<std::uint64_t>(element));
    const CourseFamily family = order[static_cast<std::size_t>(element) % order.size()];
    builder.Element(family, ++family_count[static_cast<int>(family)], random);
    builder.Flat("floor_" + std::to_string(element + 1), random);
  }
  // the end: level ground to a metre past the course's length
  builder.Ground("floor_end", std::max(1.0, course.length_m + 1.0 - builder.x()), builder.level());
  world.path_m = {Vec2(0, 0), Vec2(course.length_m, 0)};
  return world;
}

}  // namespace proxsim::gen
