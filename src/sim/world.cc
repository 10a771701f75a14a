#include "sim/world.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace proxsim {

namespace {

// The radius of a sphere about a shape's origin that holds it (a plane: unbounded).
double BoundingRadius_m(const Shape& shape) {
  if (const auto* box = std::get_if<Box>(&shape)) return 0.5 * box->size_m.norm();
  if (const auto* sphere = std::get_if<Sphere>(&shape)) return sphere->radius_m;
  if (const auto* cylinder = std::get_if<Cylinder>(&shape)) return std::hypot(cylinder->radius_m, 0.5 * cylinder->length_m);
  if (const auto* mesh = std::get_if<Mesh>(&shape)) {
    double radius_m = 0;
    for (const Vec3f& v : mesh->data->vertices_O) radius_m = std::max(radius_m, static_cast<double>(v.norm()));
    return radius_m;
  }
  return std::numeric_limits<double>::infinity();
}

// What builds the robot's bodies and says where it may stand, as text (MismatchWith).
std::string RobotKey(const Scenario& scenario, const RobotModel* model) {
  if (model == nullptr) return "";
  std::string key = model->name() + "\n" + model->source();
  if (const auto& robot = scenario.robot) {
    key += "\n" + robot->model + "\n" + std::to_string(static_cast<int>(robot->geometry)) + "\n" +
           std::to_string(robot->geom_group) + "\n" + robot->start_on;
    for (const std::string& path : robot->package_paths) key += "\n" + path;
  }
  return key;
}

std::atomic<std::int64_t> worlds_built{0};

}  // namespace

World::World(const Scenario& scenario, const RobotModel* robot_model, int threads)
    : robot_key_(RobotKey(scenario, robot_model)) {
  ++worlds_built;
  // the static world: one body, one shape per scene object, ids = scene order;
  // each moving object a body of its own, its instance moved every sample
  std::vector<BodyShape> world_shapes;
  world_shapes.reserve(scenario.scene.objects.size());
  std::vector<std::string> person_names;  // people_'s, in order
  for (const SceneObject& object : scenario.scene.objects) {
    const auto id = static_cast<std::int32_t>(object_names_.size());
    object_names_.push_back(object.name);
    scene_kinds_.push_back(std::string(ShapeKindName(object.shape)) + (object.motion ? " moving" : ""));
    if (!object.motion) {
      world_shapes.push_back({object.shape, object.X_WO, id});
      continue;
    }
    const int body = caster_.AddBody({BodyShape{object.shape, Pose::Identity(), id}}, BodyKind::kMoving, object.X_WO);
    moving_.push_back({*object.motion, body, BoundingRadius_m(object.shape), object.X_WO, object.X_WO});
    // a person's parts (NAME/torso, NAME/left_leg, ...) wait together
    if (const auto slash = object.name.find('/'); slash != std::string::npos) {
      const std::string person = object.name.substr(0, slash);
      std::size_t k = 0;
      while (k < person_names.size() && person_names[k] != person) ++k;
      if (k == person_names.size()) {
        person_names.push_back(person);
        people_.emplace_back();
      }
      moving_.back().person = static_cast<int>(k);
      people_[k].parts.push_back(moving_.size() - 1);
      if (object.name.substr(slash + 1) == "torso") people_[k].torso = moving_.size() - 1;
    }
    // (world bodies there: that caster is for distances, which measure world bodies)
    moving_caster_body_.push_back(
        moving_caster_.AddBody({BodyShape{object.shape, Pose::Identity(), id}}, BodyKind::kWorld, object.X_WO));
  }
  caster_.AddBody(std::move(world_shapes), BodyKind::kWorld);
  first_robot_object_id_ = static_cast<std::int32_t>(object_names_.size());
  // the ground is what the scene declares so (SceneObject::ground), whatever its name
  // (and the object the robot starts on on purpose, robot.start.on: it stands on it)
  const std::string start_on = scenario.robot ? scenario.robot->start_on : "";
  for (std::size_t id = 0; id < scenario.scene.objects.size(); ++id) {
    const SceneObject& object = scenario.scene.objects[id];
    if (object.ground || (!start_on.empty() && object.name == start_on)) ground_ids_.push_back(static_cast<std::int32_t>(id));
  }
  // the ground alone, in a caster of its own: a line down through an obstacle
  // resting on the floor meets the floor under it, even where the two touch
  std::vector<BodyShape> ground_shapes;
  for (const std::int32_t id : ground_ids_) {
    const SceneObject& object = scenario.scene.objects[id];
    ground_shapes.push_back({object.shape, object.X_WO, id});
  }
  ground_caster_.AddBody(std::move(ground_shapes), BodyKind::kWorld);
  ground_caster_.Commit();
  moving_caster_.Commit();

  // the robot: its links are bodies too, with object ids after the scene's
  if (robot_model != nullptr) {
    robot_model_ = std::make_unique<const RobotModel>(*robot_model);
    robot_ = std::make_unique<RobotInScene>(*robot_model_, caster_, first_robot_object_id_);
    for (int link = 0; link < robot_model->link_count(); ++link) object_names_.push_back(robot_model->link_name(link));
  }

  caster_.set_threads(threads);
  caster_.Commit();
  // the clearance truth's point-query structure over the scene without the
  // ground is built here with the other structures, not at the first sample
  if (robot_) caster_.DistanceToWorld(Vec3::Zero(), ground_ids_);
}

World::~World() = default;

std::int64_t World::BuiltCount() { return worlds_built.load(); }

std::string World::MismatchWith(const Scenario& scenario) const {
  const auto& objects = scenario.scene.objects;
  if (objects.size() != scene_kinds_.size())
    return "the scene has " + std::to_string(objects.size()) + " objects, the world " + std::to_string(scene_kinds_.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string kind = std::string(ShapeKindName(objects[i].shape)) + (objects[i].motion ? " moving" : "");
    if (objects[i].name != object_names_[i] || kind != scene_kinds_[i])
      return "scene object " + std::to_string(i) + " is '" + objects[i].name + "' (" + kind + "), the world's '" +
             object_names_[i] + "' (" + scene_kinds_[i] + ")";
  }
  const std::string robot_key = scenario.robot ? RobotKey(scenario, robot_model_.get()) : "";
  if (scenario.robot.has_value() != (robot_ != nullptr) || robot_key != robot_key_)
    return "the robot differs (its model, geometry or start surface)";
  return "";
}

void World::Claim(const void* user) {
  if (user_ != nullptr && user_ != user)
    throw std::logic_error("World::Claim: the world is held by another simulation (one at a time)");
  user_ = user;
}

void World::Release(const void* user) {
  if (user_ == user) user_ = nullptr;
}

int World::HoldPeopleNear(const Vec2& p_W_robot, double keep_m, double pass_m, double t_s, double dt_s) {
  int waiting = 0;
  for (Person& person : people_) {
    const MovingBody& torso = moving_[person.torso];
    const auto torso_at = [&](double ahead_s) -> Vec2 {
      const Pose X_WT = MotionPoseAt(torso.motion, t_s - person.waited_s + ahead_s);
      return X_WT.translation().head<2>();
    };
    const double next_m = (torso_at(0) - p_W_robot).norm();
    if (!(next_m < keep_m && next_m < (torso.X_WO.translation().head<2>() - p_W_robot).norm())) continue;
    // its walk ahead, every 0.1 s: passing by at pass_m or more, it walks on
    bool passes = std::isfinite(pass_m);
    for (double ahead_s = 0.1; passes && ahead_s <= kPassLook_s + 1e-9; ahead_s += 0.1)
      passes = (torso_at(ahead_s) - p_W_robot).norm() >= pass_m;
    if (passes) continue;
    person.waited_s += dt_s;
    ++waiting;
  }
  return waiting;
}

void World::ResetEpisode() {
  for (Person& person : people_) person.waited_s = 0;
  for (std::size_t i = 0; i < moving_.size(); ++i) {
    MovingBody& moving = moving_[i];
    moving.X_WO = moving.X_WO_start;
    caster_.SetBodyPose(moving.body, moving.X_WO);
    moving_caster_.SetBodyPose(moving_caster_body_[i], moving.X_WO);
  }
  if (robot_) robot_->ForgetClearanceBounds();
}

std::vector<std::pair<Vec2, double>> World::MovingFootprints_W() const {
  std::vector<std::pair<Vec2, double>> footprints;
  footprints.reserve(moving_.size());
  for (const MovingBody& body : moving_) footprints.emplace_back(body.X_WO.translation().head<2>(), body.radius_m);
  return footprints;
}

double World::MoveObjects(double t_s) {
  double moved_m = 0;
  for (std::size_t i = 0; i < moving_.size(); ++i) {
    MovingBody& moving = moving_[i];
    // a person who waited walks on from where it stopped
    const double waited_s = moving.person >= 0 ? people_[moving.person].waited_s : 0.0;
    const Pose X_WO = MotionPoseAt(moving.motion, t_s - waited_s);
    // a point at r from the origin moves by the origin's step plus r times the
    // turn's chord 2·sin(θ/2) = ‖R − R_last‖_F / √2 (no acos for 50 objects a sample)
    const double chord_per_m = (X_WO.linear() - moving.X_WO.linear()).norm() / std::sqrt(2.0);
    moved_m = std::max(moved_m, (X_WO.translation() - moving.X_WO.translation()).norm() + chord_per_m * moving.radius_m);
    moving.X_WO = X_WO;
    caster_.SetBodyPose(moving.body, X_WO);
    moving_caster_.SetBodyPose(moving_caster_body_[i], X_WO);
  }
  // (moving_caster_ only answers distances, which read the bodies' poses as
  // set: its top-level scene, for rays, is not rebuilt every sample)
  return moved_m;
}

}  // namespace proxsim
