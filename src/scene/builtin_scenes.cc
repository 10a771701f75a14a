// The geometry of the built-in scenes, in metres, world frame W (x forward,
// y left, z up). The robot starts at the origin and walks along +x, so each
// scene keeps a corridor |y| < 0.5 m clear from x = −0.5 to x = 3 except for
// what the robot is meant to find there.
//
// dining_room (the paper's experiment):
//   floor      infinite plane z = 0
//   walls      0.1 m thick, 2.5 m high, inner faces at x = −1, x = 5, y = ±2
//   table      top 1.2 × 0.8 × 0.04 m, upper face at z = 0.75, centred at
//              (2.0, 1.3); four cylinder legs r = 0.03 m   (y ≥ 0.9: off the corridor)
//   chairs     seat 0.42 m square at z = 0.45–0.47, four legs, a back; chair 1
//              west of the table at (1.1, 1.3), chair 2 east at (2.9, 1.3)
//   cupboard   1.0 × 0.5 × 1.8 m against the south wall, x 1.0–2.0, y −2.0…−1.5
//   obstacle   0.20 (x) × 0.30 (y) × 0.15 (z) m box centred at (2.5, 0) on the
//              floor: in the robot's way
//
// stairs (the uneven-ground course of docs/terrain.md, walked along +x; every piece spans
// y −1.5…1.5, and every top is a box's upper face):
//   floor              z = 0      x −1.0 … 1.0   (the robot starts at x = 0)
//   floor_stair_up_1   z = 0.15   x 1.0 … 1.3    4 steps up: 0.15 m rises,
//   floor_stair_up_2   z = 0.30   x 1.3 … 1.6    0.30 m treads
//   floor_stair_up_3   z = 0.45   x 1.6 … 1.9
//   floor_landing      z = 0.60   x 1.9 … 3.1    a 1.2 m landing
//   floor_stair_down_1 z = 0.45   x 3.1 … 3.4    4 steps down
//   floor_stair_down_2 z = 0.30   x 3.4 … 3.7
//   floor_stair_down_3 z = 0.15   x 3.7 … 4.0
//   floor_after_stairs z = 0      x 4.0 … 5.0
//   hole_bottom        z = −0.5   x 5.0 … 5.25   a 0.25 m hole to step over
//   floor_between_holes z = 0     x 5.25 … 6.5
//   wide_hole_bottom   z = −0.5   x 6.5 … 7.1    a 0.6 m hole no step crosses
//   floor_end          z = 0      x 7.1 … 9.0
// The pieces reach down to z = −0.5 (the holes' walls are their sides; the
// holes' bottoms are 0.1 m slabs below that). The holes are 0.5 m deep,
// deeper than the built-in biped's highest step (gait.max_step_m, 0.32 m by
// default), so the robot steps over them or not at all. Everything the feet
// stand on (the floor* pieces; not the holes' bottoms) is flagged `ground`:
// the clearance leaves it out. The floor* names are only names.
//
// Materials are plausible diffuse albedos and specular fractions (plaster
// walls bright and matte, varnished wood darker and a little glossy).
#include "scene/builtin_scenes.h"

#include <string>

namespace proxsim {

namespace {

constexpr Material kWoodFloor{0.45, 0.15};
constexpr Material kPlaster{0.85, 0.05};
constexpr Material kVarnishedWood{0.5, 0.2};
constexpr Material kPaintedWood{0.6, 0.1};
constexpr Material kCardboard{0.7, 0.0};
constexpr Material kConcrete{0.55, 0.05};
constexpr Material kDarkConcrete{0.3, 0.05};

/// A box from its full size and its centre, axis-aligned in W.
SceneObject BoxAt(std::string name, const Vec3& size_m, const Vec3& centre_W, const Material& material) {
  Pose X_WO = Pose::Identity();
  X_WO.translation() = centre_W;
  return SceneObject{std::move(name), Box{size_m}, X_WO, material};
}

/// A box from its corner bounds in W (min and max along each axis).
SceneObject BoxFromTo(std::string name, const Vec3& min_W, const Vec3& max_W, const Material& material) {
  return BoxAt(std::move(name), max_W - min_W, 0.5 * (min_W + max_W), material);
}

/// A vertical cylinder standing on z = z0 with its axis at (x, y).
SceneObject UprightCylinder(std::string name, double radius_m, double length_m, double x, double y,
                            double z0, const Material& material) {
  Pose X_WO = Pose::Identity();
  X_WO.translation() = Vec3(x, y, z0 + 0.5 * length_m);
  return SceneObject{std::move(name), Cylinder{radius_m, length_m}, X_WO, material};
}

/// A chair centred at (x, y); its back on the side of `back_dx` (−1: toward −x).
void AddChair(Scene* scene, const std::string& name, double x, double y, double back_dx) {
  constexpr double kSeat = 0.42, kSeatTop = 0.47, kSeatThickness = 0.04, kLeg = 0.03;
  constexpr double kBackHeight = 0.45;
  const double leg_height = kSeatTop - kSeatThickness;
  // seat
  scene->objects.push_back(BoxAt(name + "_seat", Vec3(kSeat, kSeat, kSeatThickness),
                                 Vec3(x, y, kSeatTop - 0.5 * kSeatThickness), kPaintedWood));
  // legs at the corners, inset by half a leg
  const double inset = 0.5 * kSeat - 0.5 * kLeg;
  int leg = 1;
  for (double dx : {-1.0, 1.0}) {
    for (double dy : {-1.0, 1.0}) {
      scene->objects.push_back(BoxAt(name + "_leg_" + std::to_string(leg++), Vec3(kLeg, kLeg, leg_height),
                                     Vec3(x + dx * inset, y + dy * inset, 0.5 * leg_height), kPaintedWood));
    }
  }
  // back, standing on the seat's rear edge
  scene->objects.push_back(BoxAt(name + "_back", Vec3(kLeg, kSeat, kBackHeight),
                                 Vec3(x + back_dx * inset, y, kSeatTop + 0.5 * kBackHeight), kPaintedWood));
}

}  // namespace

Scene MakeDiningRoomScene() {
  Scene scene;
  constexpr double kWallHeight = 2.5, kWallThickness = 0.1;
  constexpr double kXMin = -1.0, kXMax = 5.0, kYMax = 2.0;

  // floor: the whole z = 0 plane, the ground
  scene.objects.push_back(SceneObject{"floor", Plane{}, Pose::Identity(), kWoodFloor, /*ground=*/true});

  // walls: inner faces on the room's bounds, long walls overlapping the corners
  const double t = kWallThickness;
  scene.objects.push_back(BoxFromTo("wall_west", Vec3(kXMin - t, -kYMax - t, 0), Vec3(kXMin, kYMax + t, kWallHeight), kPlaster));
  scene.objects.push_back(BoxFromTo("wall_east", Vec3(kXMax, -kYMax - t, 0), Vec3(kXMax + t, kYMax + t, kWallHeight), kPlaster));
  scene.objects.push_back(BoxFromTo("wall_south", Vec3(kXMin - t, -kYMax - t, 0), Vec3(kXMax + t, -kYMax, kWallHeight), kPlaster));
  scene.objects.push_back(BoxFromTo("wall_north", Vec3(kXMin - t, kYMax, 0), Vec3(kXMax + t, kYMax + t, kWallHeight), kPlaster));

  // table: top at z = 0.75 over (2.0, 1.3), legs inset 0.06 m from its corners
  constexpr double kTableX = 2.0, kTableY = 1.3, kTableTop = 0.75, kTopThickness = 0.04;
  scene.objects.push_back(BoxAt("table_top", Vec3(1.2, 0.8, kTopThickness),
                                Vec3(kTableX, kTableY, kTableTop - 0.5 * kTopThickness), kVarnishedWood));
  int leg = 1;
  for (double dx : {-0.54, 0.54}) {
    for (double dy : {-0.34, 0.34}) {
      scene.objects.push_back(UprightCylinder("table_leg_" + std::to_string(leg++), 0.03,
                                              kTableTop - kTopThickness, kTableX + dx, kTableY + dy, 0,
                                              kVarnishedWood));
    }
  }

  // chairs on either side of the table, backs turned away from it
  AddChair(&scene, "chair_1", 1.1, kTableY, -1.0);
  AddChair(&scene, "chair_2", 2.9, kTableY, 1.0);

  // cupboard against the south wall
  scene.objects.push_back(BoxFromTo("cupboard", Vec3(1.0, -kYMax, 0), Vec3(2.0, -kYMax + 0.5, 1.8), kVarnishedWood));

  // the obstacle on the robot's way
  scene.objects.push_back(BoxAt("obstacle", Vec3(0.20, 0.30, 0.15), Vec3(2.5, 0, 0.075), kCardboard));
  return scene;
}

Scene MakeStairsScene() {
  Scene scene;
  constexpr double kY = 1.5, kBottom = -0.5;
  // a piece is ground: its top is a tread the feet stand on
  const auto piece = [&](const char* name, double x0, double x1, double z_top) {
    scene.objects.push_back(BoxFromTo(name, Vec3(x0, -kY, kBottom), Vec3(x1, kY, z_top), kConcrete));
    scene.objects.back().ground = true;
  };
  const auto hole_bottom = [&](const char* name, double x0, double x1) {
    scene.objects.push_back(BoxFromTo(name, Vec3(x0, -kY, kBottom - 0.1), Vec3(x1, kY, kBottom), kDarkConcrete));
  };
  // flat, then four steps up to the landing, four down, flat again
  piece("floor", -1.0, 1.0, 0.0);
  piece("floor_stair_up_1", 1.0, 1.3, 0.15);
  piece("floor_stair_up_2", 1.3, 1.6, 0.30);
  piece("floor_stair_up_3", 1.6, 1.9, 0.45);
  piece("floor_landing", 1.9, 3.1, 0.60);
  piece("floor_stair_down_1", 3.1, 3.4, 0.45);
  piece("floor_stair_down_2", 3.4, 3.7, 0.30);
  piece("floor_stair_down_3", 3.7, 4.0, 0.15);
  piece("floor_after_stairs", 4.0, 5.0, 0.0);
  // a hole to step over, and one too wide to cross
  hole_bottom("hole_bottom", 5.0, 5.25);
  piece("floor_between_holes", 5.25, 6.5, 0.0);
  hole_bottom("wide_hole_bottom", 6.5, 7.1);
  piece("floor_end", 7.1, 9.0, 0.0);
  return scene;
}

}  // namespace proxsim
