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
// stairs:
//   floor pieces (boxes 0.3 m thick, upper faces at z = 0, y −2…2, x −1…6)
//   around a hole x 1.3–1.7, y −0.5…0.5 (0.4 × 1 m) whose bottom is the upper
//   face of `hole_bottom` at z = −0.3. The piece the robot starts on is named
//   `floor`; the others `floor_hole_left`, `floor_hole_right`, `floor_after_hole`.
//   A platform 0.15 m high across the whole width from x = 3.0 to x = 4.5: its
//   first half `step_up` (the rising edge at x = 3.0), its second half
//   `step_down` (the falling edge at x = 4.5, back to the floor).
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

  // floor: the whole z = 0 plane
  scene.objects.push_back(SceneObject{"floor", Plane{}, Pose::Identity(), kWoodFloor});

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
  constexpr double kFloorDepth = 0.3;  // the floor boxes' thickness = the hole's depth
  constexpr double kXMin = -1.0, kXMax = 6.0, kYMax = 2.0;
  constexpr double kHoleX0 = 1.3, kHoleX1 = 1.7, kHoleY = 0.5;

  // floor pieces around the hole, upper faces at z = 0; their sides are the hole's walls
  scene.objects.push_back(BoxFromTo("floor", Vec3(kXMin, -kYMax, -kFloorDepth), Vec3(kHoleX0, kYMax, 0), kConcrete));
  scene.objects.push_back(BoxFromTo("floor_hole_left", Vec3(kHoleX0, kHoleY, -kFloorDepth), Vec3(kHoleX1, kYMax, 0), kConcrete));
  scene.objects.push_back(BoxFromTo("floor_hole_right", Vec3(kHoleX0, -kYMax, -kFloorDepth), Vec3(kHoleX1, -kHoleY, 0), kConcrete));
  scene.objects.push_back(BoxFromTo("floor_after_hole", Vec3(kHoleX1, -kYMax, -kFloorDepth), Vec3(kXMax, kYMax, 0), kConcrete));

  // the hole's bottom, 0.3 m down
  scene.objects.push_back(BoxFromTo("hole_bottom", Vec3(kHoleX0, -kHoleY, -kFloorDepth - 0.1),
                                    Vec3(kHoleX1, kHoleY, -kFloorDepth), kDarkConcrete));

  // a platform 0.15 m high: up at x = 3.0, down at x = 4.5
  constexpr double kStepHeight = 0.15;
  scene.objects.push_back(BoxFromTo("step_up", Vec3(3.0, -kYMax, 0), Vec3(3.75, kYMax, kStepHeight), kConcrete));
  scene.objects.push_back(BoxFromTo("step_down", Vec3(3.75, -kYMax, 0), Vec3(4.5, kYMax, kStepHeight), kConcrete));
  return scene;
}

}  // namespace proxsim
