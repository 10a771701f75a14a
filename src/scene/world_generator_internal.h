// Internal to the world generators (world_generator.cc, world_course.cc,
// world_room.cc): the draws and the objects' constructors they share.
#pragma once

#include <string>

#include "scene/keyed_random.h"
#include "scene/world_generator.h"

namespace proxsim::gen {

/// A course's ground pieces are slabs this thick below their tops (deeper than any hole).
constexpr double kCourseSlab_m = 1.0;

/// Rounded to the millimetre.
double Round_m(double value);

/// A value within `range` at `difficulty` (world_generator.h, GenRange).
double Draw(const GenRange& range, double difficulty, KeyedRandom& random);

/// A direction drawn uniformly on the circle by rejection from the square
/// [−1, 1]², from arithmetic and sqrt alone (not libm's cos and sin of a drawn
/// angle: their bits depend on the CPU, see portable_trig.h).
Vec2 UniformDirection(KeyedRandom& random);

/// An axis-aligned box from its corners, rounded to the millimetre.
GenObject Box(std::string name, const Vec3& min_W, const Vec3& max_W, bool ground, double albedo);

GeneratedWorld GenerateCourse(const GenerateConfig& config);
GeneratedWorld GenerateRoom(const GenerateConfig& config);

}  // namespace proxsim::gen
