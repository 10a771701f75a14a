// Generated worlds (docs/worlds.md): a course of sub-terrains walked along
// +x, or a furnished room with people walking through it, from a kind, a
// seed and a difficulty in [0, 1]. The same configuration gives the same
// world on every machine (scene/keyed_random.h). A generated world is plain
// data — objects with shapes, poses, roles and motions, the robot's start
// and path — that the scenario layer writes out as a plain scenario
// (`proxsim generate`) and reads back, so a generated run and the run of its
// written file are the same run.
//
// Every number a generator draws is rounded (lengths to the millimetre,
// angles to a tenth of a degree, speeds to the cm/s) before it shapes
// anything, so what is written is exactly what was checked.
//
// Frames: W world; the robot starts at the origin facing +x.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry.h"

namespace proxsim {

/// A range [easy, hard] of one parameter: at difficulty d a value is drawn
/// uniformly between easy and easy + d·(hard − easy).
struct GenRange {
  double easy = 0;
  double hard = 0;
};

/// The course's families, in their default order.
enum class CourseFamily { kStairsUp, kStairsDown, kHole, kPit, kGap, kStep, kBoxes, kRamp };
/// Names in CourseFamily order: stairs_up, stairs_down, hole, pit, gap, step, boxes, ramp.
const std::vector<std::string>& CourseFamilyNames();

struct CourseConfig {
  double length_m = 20.0;     ///< along +x from the start, > 2
  double width_m = 2.0;       ///< across, > 0.5
  std::vector<CourseFamily> elements;  ///< the order walked (cycled); empty: every family in turn, shuffled by the seed
  // the families' ranges, easy → hard
  GenRange stairs_rise_m{0.05, 0.18};
  GenRange stairs_tread_m{0.40, 0.28};  ///< never below kFootLength_m
  GenRange stairs_steps{2, 6};
  GenRange hole_width_m{0.10, 0.45};
  GenRange hole_depth_m{0.10, 0.60};
  GenRange pit_width_m{0.60, 1.20};
  GenRange pit_depth_m{0.03, 0.15};
  GenRange gap_width_m{0.10, 0.40};
  GenRange step_height_m{0.03, 0.18};
  GenRange boxes_height_m{0.01, 0.10};
  GenRange ramp_slope_deg{3, 15};
  GenRange flat_m{1.2, 0.6};            ///< flat ground between elements
};

struct RoomConfig {
  Vec2 size_m{10, 10};        ///< inner size along x and y, each >= 3
  double height_m = 2.6;      ///< the walls' height, > the tallest person
  double robot_width_m = 0.45;  ///< the corridor's width is this plus margin_m
  double margin_m = 0.2;
  GenRange tables{1, 4};
  GenRange chairs{2, 8};
  GenRange shelves{1, 4};
  GenRange clutter{2, 15};
  /// Obstacles put in the way: on the straight walk from the start to the
  /// goal (the robot's path), each leaving a way around (the corridor). A
  /// count per 5 m of that walk (at least one), then each one's width across
  /// the walk and height: more, thinner and lower as the difficulty grows.
  GenRange blockers{1, 3};
  GenRange blocker_width_m{0.6, 0.12};
  GenRange blocker_height_m{0.6, 0.10};
  GenRange people{0, 4};
  GenRange person_height_m{1.55, 1.95};
  GenRange person_speed_m_s{0.6, 1.4};
};

struct GenerateConfig {
  enum class Kind { kCourse, kRoom };
  Kind kind = Kind::kCourse;
  std::uint64_t seed = 1;
  double difficulty = 0.5;  ///< in [0, 1]
  CourseConfig course;
  RoomConfig room;
};

/// The builtin biped's foot length: no tread may be shorter.
constexpr double kFootLength_m = 0.26;

/// The problems of a configuration (an impossible range, a tread shorter
/// than a foot, a negative depth, a person taller than the room); none when valid.
std::vector<std::string> GenerateProblems(const GenerateConfig& config);

/// One object of a generated world, as a scenario writes it.
struct GenObject {
  std::string name;  ///< by its role: hole_3, stairs_up_1_step_2, chair_4_seat, person_2
  enum class Kind { kBox, kCylinder, kSphere, kPlane, kPerson };
  Kind kind = Kind::kBox;
  Vec3 size_m = Vec3::Zero();  ///< box: full extents; cylinder: (radius, radius, length); sphere: radius in x; person: height in z
  Vec3 xyz_m = Vec3::Zero();
  Vec3 rpy_deg = Vec3::Zero();
  bool ground = false;
  double albedo = 0.6;
  // a person's walk: waypoints there and back, from start_s on
  std::vector<Vec2> waypoints_m;
  double speed_m_s = 0;
  double start_s = 0;
};

struct GeneratedWorld {
  std::vector<GenObject> objects;
  std::vector<Vec2> path_m;  ///< the robot's waypoints, from its start (the origin)
  /// The room's free corridor: the cells searched (for pictures and tests), metres per cell.
  double corridor_cell_m = 0;
  /// A room's way around what is in the path's way: waypoints from the start
  /// to the goal along the free corridor (a proof that a way exists; the
  /// robot is given the straight path_m and must find it by sensing).
  std::vector<Vec2> corridor_m;
};

/// Generates a world; requires GenerateProblems(config) to be empty.
GeneratedWorld GenerateWorld(const GenerateConfig& config);

}  // namespace proxsim
