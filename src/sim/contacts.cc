#include "sim/contacts.h"

#include <algorithm>
#include <limits>
#include <map>
#include <variant>

#include "raycast/analytic_shapes.h"
#include "scene/shape_inside.h"

namespace proxsim {

namespace {

// Links searched up each leg from its foot for self-collision: the foot, the
// shank and the thigh (links without shapes are passed over).
constexpr int kLegLinks = 3;

// How far p_O lies from a link shape (0 inside, with `depth_m` how deep):
// closed forms for the solids; for a mesh, its nearest triangle.
double DistanceToLinkShape(const Shape& shape, const Vec3& p_O, double* depth_m) {
  *depth_m = 0;
  double distance_m = std::numeric_limits<double>::infinity();
  if (const auto* box = std::get_if<Box>(&shape)) distance_m = DistanceToBox(*box, p_O);
  else if (const auto* sphere = std::get_if<Sphere>(&shape)) distance_m = DistanceToSphere(*sphere, p_O);
  else if (const auto* cylinder = std::get_if<Cylinder>(&shape)) distance_m = DistanceToCylinder(*cylinder, p_O);
  else if (const auto* mesh = std::get_if<Mesh>(&shape)) {
    const TriangleMesh& data = *mesh->data;
    for (const auto& t : data.triangles) {
      const auto corner = [&](int k) { return Vec3(data.vertices_O[t[k]].cast<double>().cwiseProduct(mesh->scale)); };
      distance_m = std::min(distance_m, DistanceToTriangle(p_O, corner(0), corner(1), corner(2)));
    }
    return distance_m;
  }
  if (distance_m == 0) *depth_m = std::max(DepthInside_m(shape, p_O), 0.0);
  return distance_m;
}

// The axis-aligned box of some points, grown by `margin_m`.
ContactFinder::Aabb BoxOf(const std::vector<Vec3>& points, double margin_m) {
  ContactFinder::Aabb box;
  for (const Vec3& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  box.lo.array() -= margin_m;
  box.hi.array() += margin_m;
  return box;
}

// Whether two boxes, each fixed in its link (pose in W), are apart: a
// separating axis among their faces' normals and the cross products of
// their edges (the 15 axes of two oriented boxes).
bool Apart(const ContactFinder::Aabb& a_L, const Pose& X_WA, const ContactFinder::Aabb& b_L, const Pose& X_WB) {
  const Vec3 ca = X_WA * ((a_L.lo + a_L.hi) / 2), cb = X_WB * ((b_L.lo + b_L.hi) / 2);
  const Vec3 ha = (a_L.hi - a_L.lo) / 2, hb = (b_L.hi - b_L.lo) / 2;
  const Eigen::Matrix3d Ra = X_WA.linear(), Rb = X_WB.linear();
  const Vec3 d = cb - ca;
  const auto separates = [&](const Vec3& n) {
    if (n.squaredNorm() < 1e-18) return false;
    double ra = 0, rb = 0;
    for (int i = 0; i < 3; ++i) {
      ra += ha[i] * std::abs(n.dot(Ra.col(i)));
      rb += hb[i] * std::abs(n.dot(Rb.col(i)));
    }
    return std::abs(d.dot(n)) > ra + rb;
  };
  for (int i = 0; i < 3; ++i)
    if (separates(Ra.col(i)) || separates(Rb.col(i))) return true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (separates(Ra.col(i).cross(Rb.col(j)))) return true;
  return false;
}

// Keeps the deepest sample of each (link, object, other link).
void Keep(std::map<std::tuple<int, std::int32_t, int>, Contact>& kept, const Contact& contact) {
  const auto key = std::make_tuple(contact.link, contact.object_id, contact.other_link);
  const auto found = kept.find(key);
  if (found == kept.end() || contact.depth_m > found->second.depth_m) kept[key] = contact;
}

}  // namespace

ContactFinder::ContactFinder(RobotInScene& robot, const RayCaster& ground, std::span<const std::int32_t> ground_ids,
                             std::span<const FootFrame> feet)
    : robot_(robot), ground_(ground), ground_ids_(ground_ids.begin(), ground_ids.end()) {
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
      // height above the sole along its upward normal (a foot link's frame may be turned any way)
      if ((points_L[i] - foot.p_L_sole).dot(foot.up_L) < kSoleBand_m) not_sole_[foot.link][i] = false;
  }
  // the legs' lower links, each of one leg against each of the other, with
  // the boxes that bound their samples and their shapes in their own frames
  if (feet.size() == 2 && feet[0].link >= 0 && feet[1].link >= 0) {
    for (int a : LegLinks(feet[0].link))
      for (int b : LegLinks(feet[1].link))
        if (a != b) leg_pairs_.emplace_back(a, b);
  }
  for (const auto& [a, b] : leg_pairs_) {
    for (int link : {a, b}) {
      if (leg_links_.count(link)) continue;
      LegLink& leg = leg_links_[link];
      leg.samples_box_L = BoxOf(robot_.surface_points_L(link), kContactTolerance_m);
      for (const LinkShape& shape : model.link(link).shapes) {
        std::vector<Vec3> vertices_O;
        if (const auto* mesh = std::get_if<Mesh>(&shape.shape))
          for (const Vec3f& v : mesh->data->vertices_O) vertices_O.push_back(v.cast<double>().cwiseProduct(mesh->scale));
        leg.shapes.push_back({&shape.shape, shape.X_LO.inverse(),
                              vertices_O.empty() ? Aabb{} : BoxOf(vertices_O, kContactTolerance_m)});
      }
    }
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

std::vector<Contact> ContactFinder::Find(double clearance_to_objects_m) {
  std::map<std::tuple<int, std::int32_t, int>, Contact> kept;
  const auto keep_near = [&](std::span<const std::int32_t> exclude, const RobotInScene::SampleMask* mask,
                             const RayCaster* against) {
    // the cheap running bound first: nothing within reach, nothing to look at
    if (robot_.ClearanceTo(exclude, kContactTolerance_m, mask, against) >= kContactTolerance_m) return;
    for (const RobotInScene::NearSample& near : robot_.SamplesNear(exclude, kContactTolerance_m, mask, against))
      Keep(kept, Contact{near.link, near.nearest.object_id, -1, near.nearest.depth_m, near.p_W});
  };
  // obstacles, furniture: any sample, unless the clearance already keeps them apart
  if (clearance_to_objects_m <= kContactTolerance_m) keep_near(ground_ids_, nullptr, nullptr);
  // the moving objects, in their own caster
  if (moving_) keep_near({}, nullptr, moving_);
  // the ground (its caster alone): anything but a sole, when the feet are known (not for a replayed trajectory)
  if (has_feet_) keep_near({}, &not_sole_, &ground_);
  std::vector<Contact> contacts;
  for (auto& [key, contact] : kept) contacts.push_back(contact);
  FindSelfContacts(contacts);
  return contacts;
}

void ContactFinder::FindSelfContacts(std::vector<Contact>& contacts) const {
  for (const auto& [left, right] : leg_pairs_) {
    // each link's samples against the other's shapes, both ways: the deepest is the pair's contact
    Contact deepest{left, -1, right, -1, Vec3::Zero()};
    if (Apart(leg_links_.at(left).samples_box_L, robot_.X_WL(left), leg_links_.at(right).samples_box_L,
              robot_.X_WL(right))) {
      continue;
    }
    for (const auto& [a, b] : {std::pair{left, right}, std::pair{right, left}}) {
      const LegLink& leg_b = leg_links_.at(b);
      const Pose X_BA = robot_.X_WL(b).inverse() * robot_.X_WL(a);
      for (const Vec3& p_A : robot_.surface_points_L(a)) {
        // only samples within b's bounding box can touch it
        const Vec3 p_B = X_BA * p_A;
        if (!leg_b.samples_box_L.Contains(p_B)) continue;
        for (const LegShape& shape : leg_b.shapes) {
          const Vec3 p_O = shape.X_OL * p_B;
          if (shape.mesh_box_O.Bounded() && !shape.mesh_box_O.Contains(p_O)) continue;
          double depth_m = 0;
          const double distance_m = DistanceToLinkShape(*shape.shape, p_O, &depth_m);
          if (distance_m <= kContactTolerance_m && depth_m > deepest.depth_m) {
            deepest = {a, -1, b, depth_m, robot_.X_WL(a) * p_A};
          }
        }
      }
    }
    if (deepest.depth_m >= 0) contacts.push_back(deepest);
  }
}

}  // namespace proxsim
