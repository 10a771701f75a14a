// The world a simulation builds once and keeps across episodes: the scene's
// objects and the robot's links as bodies in the ray caster (with their
// acceleration structures) and the object table that names what a ray hits.
// An episode (sim/simulation.h) moves the robot's bodies and the scene's
// moving objects (instances whose transforms change: no BVH is rebuilt);
// nothing here is rebuilt between episodes. The sensors are not part of it
// (sim/sensor_rig.h): one world serves simulations with different sensors,
// strategies and gaits in turn — one at a time, each claiming it while it
// lives (an outcome study builds one world per job, not one per run).
//
// Frames: W world, L a link, O a scene object.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "scenario/scenario.h"
#include "raycast/ray_caster.h"
#include "robot/robot_model.h"
#include "sim/caster_terrain.h"
#include "sim/robot_in_scene.h"

namespace proxsim {

class World {
 public:
  /// Builds the scene's and the robot's bodies (robot_model null: no robot)
  /// and commits them. The world keeps its own copies of the scene's motions
  /// and of the robot model: neither argument need outlive it.
  World(const Scenario& scenario, const RobotModel* robot_model, int threads);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  RayCaster& caster() { return caster_; }
  const RayCaster& caster() const { return caster_; }
  /// The scene's true ground for the gait's footsteps: the objects flagged
  /// `ground` only (an obstacle is never stepped on).
  const TerrainQuery& terrain() const { return terrain_; }

  /// The objects flagged `ground`, alone, in a caster of their own (object ids as in caster()).
  const RayCaster& ground_caster() const { return ground_caster_; }

  /// Object ids: the scene's objects in scenario order, then the robot's links.
  const std::string& object_name(std::int32_t object_id) const { return object_names_.at(object_id); }
  const std::vector<std::string>& object_names() const { return object_names_; }
  /// Object ids from here on are robot links.
  std::int32_t first_robot_object_id() const { return first_robot_object_id_; }
  /// The objects the feet stand on (flagged `ground` in the scene), left out of the clearance.
  std::span<const std::int32_t> ground_ids() const { return ground_ids_; }

  /// The robot's bodies, or null without a robot.
  RobotInScene* robot() { return robot_.get(); }
  const RobotInScene* robot() const { return robot_.get(); }

  /// Puts every moving object where it is at t_s (takes effect at the
  /// caster's next Commit()); returns how far any of their points moved at
  /// most since the last call (a bound: translation plus the turn's chord × radius).
  double MoveObjects(double t_s);
  /// Whether the scene has moving objects (they are bodies of their own in caster()).
  bool has_moving_objects() const { return !moving_.empty(); }
  /// Pedestrians do not walk into a robot: each person (the moving parts
  /// `NAME/...` of a person, scene/person.h) whose next step, at t_s, would
  /// bring its torso nearer than `keep_m` to `p_W_robot` and nearer than it
  /// is now waits where it is for `dt_s` (its walk resumes from there later)
  /// — unless its walk over the next kPassLook_s stays at least `pass_m`
  /// from the robot: it passes by (infinity: it always waits). Call before
  /// MoveObjects(t_s); returns how many wait.
  int HoldPeopleNear(const Vec2& p_W_robot, double keep_m, double pass_m, double t_s, double dt_s);
  /// How far ahead a person looks at its own walk to pass a robot, s.
  static constexpr double kPassLook_s = 2.0;
  /// Where each moving object is (its origin's x, y) and the radius of a
  /// sphere about its origin that holds it.
  std::vector<std::pair<Vec2, double>> MovingFootprints_W() const;
  /// The moving objects alone, in a caster of their own (object ids as in
  /// caster()), for the robot's clearance and contacts (caster()'s distances
  /// measure the still scene only); null without any.
  const RayCaster* moving_caster() const { return moving_.empty() ? nullptr : &moving_caster_; }


  /// The robot model its bodies were built from; null without a robot.
  const RobotModel* robot_model() const { return robot_model_.get(); }
  /// Empty when `scenario` describes this world (its scene's objects by name
  /// and kind, and its robot's model and start surface), else what differs:
  /// a simulation runs on a shared world only if built from the same scene and robot.
  std::string MismatchWith(const Scenario& scenario) const;

  /// A simulation takes the world for its lifetime (std::logic_error if
  /// another holds it: an episode's bodies are the world's) and hands it back.
  void Claim(const void* user);
  void Release(const void* user);
  /// A new episode: every moving object back at its start and every person
  /// walking from its start again; the robot's clearance measure starts afresh.
  void ResetEpisode();

  /// Worlds built in this process so far (the bench counts an outcome study's).
  static std::int64_t BuiltCount();

 private:
  RayCaster caster_;
  RayCaster ground_caster_;            // the objects flagged ground, alone: where feet may land
  CasterTerrain terrain_{ground_caster_};
  std::vector<std::string> object_names_;
  std::int32_t first_robot_object_id_ = 0;
  std::vector<std::int32_t> ground_ids_;
  std::unique_ptr<const RobotModel> robot_model_;  // the bodies' (robot_ reads it)
  std::unique_ptr<RobotInScene> robot_;
  std::string robot_key_;                           // what built the robot's bodies (MismatchWith)
  std::vector<std::string> scene_kinds_;            // each scene object's shape kind, moving or not
  const void* user_ = nullptr;                      // the simulation holding the world
  struct MovingBody {
    Motion motion;         // the scenario's, copied
    int body;              // in caster_
    double radius_m;       // of a sphere about the object's origin holding it
    Pose X_WO;             // where it was last put
    Pose X_WO_start;       // where the scenario puts it
    int person = -1;       // the person whose part it is (people_), -1 for none
  };
  // a person: its parts in moving_, the torso among them, and how long it has waited
  struct Person {
    std::vector<std::size_t> parts;
    std::size_t torso = 0;
    double waited_s = 0;
  };
  std::vector<Person> people_;
  std::vector<MovingBody> moving_;
  RayCaster moving_caster_;
  std::vector<int> moving_caster_body_;  // each moving object's body in moving_caster_
};

}  // namespace proxsim
