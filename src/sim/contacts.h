// The robot's body meeting the world and itself: every sample, the robot's
// links (their surfaces sampled every 2 cm, RobotInScene) against the scene's
// objects, and the links of one leg against those of the other. A contact is
// anything but a foot's sole on the ground: a leg or foot striking an
// obstacle, a table, a riser (the ground's side: any part of the robot but a
// sole touching a ground object), or the swing foot touching the stance leg.
// The ground and the legs are checked where the feet are known (the robot's
// own gait; a replayed trajectory names none): elsewhere only the objects.
//
// Accuracy: a contact is reported where a surface sample lies inside an
// object or within kContactTolerance_m of it. Samples lie on the surface, so
// a reported contact is never farther than that tolerance; an overlap thinner
// than the 2 cm between samples can go unseen until it deepens (a sample or
// two at walking speeds: a swinging foot moves 1-3 cm per 10 ms).
//
// Frames: W world, L a link, O a shape in its link.
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "gait/locomotion.h"
#include "sim/robot_in_scene.h"

namespace proxsim {

/// A sample within this distance of an object touches it, m: contact means
/// overlap or touching, to well above the distances' rounding (a swing foot
/// of the gait may pass a riser 0.3 mm away, stairs_walk.yaml: not a contact).
constexpr double kContactTolerance_m = 1e-4;
/// A foot's surface within this height above its sole plane (along the foot
/// link's z) is its sole: it may touch the ground it stands on, m.
constexpr double kSoleBand_m = 0.02;

/// One contact at one sample: a link touching a scene object or another link.
struct Contact {
  int link = -1;                ///< the robot link
  std::int32_t object_id = -1;  ///< the scene object touched; -1 when it is a link (self-collision)
  int other_link = -1;          ///< the other link of a self-collision; -1 otherwise
  double depth_m = 0;           ///< how deep the deepest sample lies inside (0: touching, for meshes: unknown)
  Vec3 p_W = Vec3::Zero();      ///< that sample, in the world
};

class ContactFinder {
 public:
  /// `robot` and `ground` must outlive this; `ground` holds the objects
  /// `ground_ids` (the robot's caster's ids) alone; `feet` are the robot's
  /// feet (their soles may touch the ground); empty for a robot without legs.
  ContactFinder(RobotInScene& robot, const RayCaster& ground, std::span<const std::int32_t> ground_ids,
                std::span<const FootFrame> feet);

  /// The scene's moving objects: `moving` holds them alone (their ids as in
  /// the robot's caster, whose distances measure the still scene only); they
  /// are measured there every sample. Null: none.
  void SetMoving(const RayCaster* moving) { moving_ = moving; }

  /// The contacts at the pose the robot was last placed at, one per (link,
  /// object or other link), the deepest sample of each.
  /// `clearance_to_objects_m`: the robot's clearance to every object but the
  /// ground at this pose as far as it is known (RobotInScene::ClearanceTo;
  /// a lower bound is enough, 0 when unknown): above the contact tolerance,
  /// no object is looked at again.
  std::vector<Contact> Find(double clearance_to_objects_m = 0);

 private:
  // one leg's lower links (foot up to the thigh), for self-collision
  std::vector<int> LegLinks(int foot_link) const;
  void FindSelfContacts(std::vector<Contact>& contacts) const;

  // what self-collision reads of a leg link, made once: the box bounding its
  // samples, and each shape with its frame and (a mesh) the box of its vertices
 public:
  struct Aabb {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
    bool Bounded() const { return (lo.array() <= hi.array()).all(); }
    bool Contains(const Vec3& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
  };

 private:
  struct LegShape {
    const Shape* shape;
    Pose X_OL;
    Aabb mesh_box_O;  // unbounded (empty) for a solid
  };
  struct LegLink {
    Aabb samples_box_L;
    std::vector<LegShape> shapes;
  };

  RobotInScene& robot_;
  std::map<int, LegLink> leg_links_;
  const RayCaster& ground_;                   // the ground alone
  std::vector<std::int32_t> ground_ids_;      // objects the soles may touch
  const RayCaster* moving_ = nullptr;         // the moving objects alone, or null
  RobotInScene::SampleMask not_sole_;          // the samples that may not touch the ground
  bool has_feet_ = false;                      // without feet (a replayed trajectory) the ground is not checked
  std::vector<std::pair<int, int>> leg_pairs_;  // (left leg link, right leg link)
};

}  // namespace proxsim
