#include "sim/contacts.h"

#include <algorithm>
#include <limits>
#include <map>

#include "raycast/analytic_shapes.h"

namespace proxsim {

namespace {

// Links searched up each leg from its foot for self-collision: the foot, the
// shank and the thigh (links without shapes are passed over).
constexpr int kLegLinks = 3;

// A bounding sphere of a link's surface samples, in its link frame.
struct LinkSphere {
  Vec3 center_L = Vec3::Zero();
  double radius_m = -1;  // < 0: no samples
};

LinkSphere SphereOf(const std::vector<Vec3>& points_L) {
  LinkSphere sphere;
  if (points_L.empty()) return sphere;
  Vec3 lo = points_L[0], hi = lo;
  for (const Vec3& p : points_L) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  sphere.center_L = (lo + hi) / 2;
  sphere.radius_m = 0;
  for (const Vec3& p : points_L) sphere.radius_m = std::max(sphere.radius_m, (p - sphere.center_L).norm());
  return sphere;
}

// How far p_O lies from a link shape (0 inside, with `depth_m` how deep):
// closed forms for the solids; for a mesh, its nearest triangle, only when
// p_O is within the mesh's bounding box grown by `within_m` (else +inf).
double DistanceToLinkShape(const Shape& shape, const Vec3& p_O, double within_m, double* depth_m) {
  *depth_m = 0;
  double distance_m = std::numeric_limits<double>::infinity();
  if (const auto* box = std::get_if<Box>(&shape)) distance_m = DistanceToBox(*box, p_O);
  else if (const auto* sphere = std::get_if<Sphere>(&shape)) distance_m = DistanceToSphere(*sphere, p_O);
  else if (const auto* cylinder = std::get_if<Cylinder>(&shape)) distance_m = DistanceToCylinder(*cylinder, p_O);
  else if (const auto* mesh = std::get_if<Mesh>(&shape)) {
    const TriangleMesh& data = *mesh->data;
    if (data.vertices_O.empty()) return distance_m;
    Vec3 lo = data.vertices_O[0].cast<double>().cwiseProduct(mesh->scale), hi = lo;
    for (const Vec3f& v : data.vertices_O) {
      const Vec3 p = v.cast<double>().cwiseProduct(mesh->scale);
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    if (((p_O - hi).array() > within_m).any() || ((lo - p_O).array() > within_m).any()) return distance_m;
    for (const auto& t : data.triangles) {
      const auto corner = [&](int k) { return Vec3(data.vertices_O[t[k]].cast<double>().cwiseProduct(mesh->scale)); };
      distance_m = std::min(distance_m, DistanceToTriangle(p_O, corner(0), corner(1), corner(2)));
    }
    return distance_m;
  }
  if (distance_m == 0) *depth_m = DepthInside(shape, p_O);
  return distance_m;
}

// Keeps the deepest sample of each (link, object, other link).
void Keep(std::map<std::tuple<int, std::int32_t, int>, Contact>& kept, const Contact& contact) {
  const auto key = std::make_tuple(contact.link, contact.object_id, contact.other_link);
  const auto found = kept.find(key);
  if (found == kept.end() || contact.depth_m > found->second.depth_m) kept[key] = contact;
}

}  // namespace

ContactFinder::ContactFinder(RobotInScene& robot, std::int32_t scene_object_count,
                             std::span<const std::int32_t> ground_ids, std::span<const FootFrame> feet)
    : robot_(robot), ground_ids_(ground_ids.begin(), ground_ids.end()) {
  for (std::int32_t id = 0; id < scene_object_count; ++id)
    if (std::find(ground_ids_.begin(), ground_ids_.end(), id) == ground_ids_.end()) not_ground_ids_.push_back(id);
  // against the ground every sample counts but a foot's sole band
  const RobotModel& model = robot_.model();
  not_sole_.resize(model.link_count());
  for (int link = 0; link < model.link_count(); ++link)
    not_sole_[link].assign(robot_.surface_points_L(link).size(), true);
  for (const FootFrame& foot : feet) {
    if (foot.link < 0) continue;
    has_feet_ = true;
    const auto& points_L = robot_.surface_points_L(foot.link);
    for (std::size_t i = 0; i < points_L.size(); ++i)
      if (points_L[i].z() - foot.p_L_sole.z() < kSoleBand_m) not_sole_[foot.link][i] = false;
  }
  // the legs' lower links, each of one leg against each of the other
  if (feet.size() == 2 && feet[0].link >= 0 && feet[1].link >= 0) {
    for (int a : LegLinks(feet[0].link))
      for (int b : LegLinks(feet[1].link))
        if (a != b) leg_pairs_.emplace_back(a, b);
  }
}

std::vector<int> ContactFinder::LegLinks(int foot_link) const {
  const RobotModel& model = robot_.model();
  std::vector<int> links;
  for (int link = foot_link; link >= 0 && static_cast<int>(links.size()) < kLegLinks;) {
    if (!robot_.surface_points_L(link).empty()) links.push_back(link);
    const int joint = model.link(link).parent_joint;
    if (joint < 0) break;
    link = model.joint(joint).parent_link;
    if (link == model.root_link()) break;  // the pelvis joins the legs: not a leg link
  }
  return links;
}

std::vector<Contact> ContactFinder::Find() {
  std::map<std::tuple<int, std::int32_t, int>, Contact> kept;
  const auto keep_near = [&](std::span<const std::int32_t> exclude, const RobotInScene::SampleMask* mask) {
    // the cheap running bound first: nothing within reach, nothing to look at
    if (robot_.ClearanceTo(exclude, kContactTolerance_m, mask) >= kContactTolerance_m) return;
    for (const RobotInScene::NearSample& near : robot_.SamplesNear(exclude, kContactTolerance_m, mask))
      Keep(kept, Contact{near.link, near.nearest.object_id, -1, near.nearest.depth_m, near.p_W});
  };
  keep_near(ground_ids_, nullptr);  // obstacles, furniture: any sample
  // the ground: anything but a sole, when the feet are known (not for a replayed trajectory)
  if (has_feet_) keep_near(not_ground_ids_, &not_sole_);
  std::vector<Contact> contacts;
  for (auto& [key, contact] : kept) contacts.push_back(contact);
  FindSelfContacts(contacts);
  return contacts;
}

void ContactFinder::FindSelfContacts(std::vector<Contact>& contacts) const {
  const RobotModel& model = robot_.model();
  for (const auto& [left, right] : leg_pairs_) {
    // each link's samples against the other's shapes, both ways: the deepest is the pair's contact
    Contact deepest{left, -1, right, -1, Vec3::Zero()};
    for (const auto& [a, b] : {std::pair{left, right}, std::pair{right, left}}) {
      const auto& points_L = robot_.surface_points_L(a);
      const LinkSphere sphere_a = SphereOf(points_L), sphere_b = SphereOf(robot_.surface_points_L(b));
      if (sphere_a.radius_m < 0 || sphere_b.radius_m < 0) continue;
      const Pose& X_WA = robot_.X_WL(a);
      const Pose& X_WB = robot_.X_WL(b);
      if ((X_WA * sphere_a.center_L - X_WB * sphere_b.center_L).norm() >
          sphere_a.radius_m + sphere_b.radius_m + kContactTolerance_m) {
        continue;
      }
      const Pose X_BA = X_WB.inverse() * X_WA;
      for (const Vec3& p_A : points_L) {
        const Vec3 p_B = X_BA * p_A;
        if ((p_B - sphere_b.center_L).norm() > sphere_b.radius_m + kContactTolerance_m) continue;
        for (const LinkShape& shape : model.link(b).shapes) {
          double depth_m = 0;
          const double distance_m =
              DistanceToLinkShape(shape.shape, shape.X_LO.inverse() * p_B, kContactTolerance_m, &depth_m);
          if (distance_m <= kContactTolerance_m && depth_m > deepest.depth_m) deepest = {a, -1, b, depth_m, X_WA * p_A};
        }
      }
    }
    if (deepest.depth_m >= 0) contacts.push_back(deepest);
  }
}

}  // namespace proxsim
