// The referee of an episode: an observer of each sample's facts — the
// robot's state, its clearance, its contacts, the legs' events, the stop
// commands — that judges the episode: whether the robot reached its goal,
// stands (since when, and why), collided, fell, and how the episode ended,
// as a typed EpisodeOutcome (docs/outcomes.md). It reads the truth (contacts,
// clearance): no strategy sees it. The simulation (sim/simulation.h) feeds
// it; nothing it decides feeds back into the loop but the end of an episode.
//
// Frames: W world, P pelvis.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/geometry.h"
#include "gait/locomotion.h"
#include "scenario/scenario.h"
#include "strategy/strategy.h"

namespace proxsim {


/// How an episode ended (summary.json `robot.outcome`; docs/outcomes.md).
enum class OutcomeKind { kReachedGoal, kStopped, kCollided, kFell, kRefused, kTimeUp };
/// Every outcome's name, in OutcomeKind's order.
inline constexpr std::array<std::string_view, 6> kOutcomeNames = {"reached_goal", "stopped", "collided",
                                                                  "fell",         "refused", "time_up"};
constexpr std::string_view OutcomeName(OutcomeKind kind) { return kOutcomeNames[static_cast<std::size_t>(kind)]; }
/// The outcome of a name (a journal's, a summary's); empty for none.
std::optional<OutcomeKind> OutcomeFromName(std::string_view name);

/// An episode's outcome: its kind, when, and a line for a person.
struct EpisodeOutcome {
  OutcomeKind kind = OutcomeKind::kTimeUp;
  double t_s = 0;
  std::string detail;
  std::string_view name() const { return OutcomeName(kind); }
};

/// What the episode knows of the robot so far (summary.json `robot`).
struct RobotOutcome {
  bool stop_requested = false;
  double stop_request_t_s = 0;   ///< when a stop was first commanded
  /// Standing still at the last sample, and since when, and why: `strategy`
  /// (a stop command not resumed), `cannot_step` (the legs stood before a
  /// step they cannot take), `own_map` (the gait, planning on the robot's
  /// own map, found no step it can take there) or `end_of_path` (the path
  /// or the trajectory ended). At the end of an episode: standing still for good.
  bool stopped = false;
  double stop_t_s = 0;
  std::string stop_reason;
  bool reached_goal = false;     ///< the pelvis came within half a stride of the path's last waypoint
  double reached_goal_t_s = 0;
  double min_clearance_m = std::numeric_limits<double>::infinity();
  double min_clearance_t_s = 0;
  /// Contacts of the robot's body with the world or itself (sim/contacts.h),
  /// each logged when it begins: link, object or other link, depth, point.
  struct Collision {
    double t_s = 0;
    std::string link;
    std::string object;  ///< the scene object, or the other link of a self-collision
    bool self = false;
    double depth_m = 0;
    Vec3 p_W = Vec3::Zero();
  };
  std::vector<Collision> collisions;
  bool collided = false;  ///< a contact ended the episode (on_collision: stop)
  bool fell = false;      ///< an unsafe step was taken (unsafe_steps: fall), or a foot landed where it cannot stand (footholds: map)
  std::optional<Vec3> fall_p_W;  ///< where it fell: the foothold the foot missed (the middle of its sole as planned), or the pelvis's point on the ground; empty unless it fell
  std::string fall_reason;       ///< why it fell (what the legs said); empty unless it fell
  bool ended = false;     ///< the episode ended before its last sample (collided or fell)
  double end_t_s = 0;
  std::string end_detail;
};

/// A contact of the robot's body as the referee is told of it: which link
/// touched which object or other link, by name (the simulation names them).
struct BodyContact {
  std::string link;
  std::string object;  ///< the scene object, or the other link of a self-collision
  bool self = false;
  double depth_m = 0;  ///< how deep the deepest sample lies inside (0: touching, for meshes: unknown)
  Vec3 p_W = Vec3::Zero();
};

class Referee {
 public:
  /// For the scenario's robot (its on_collision, unsafe_steps, footholds and
  /// path); `goal_tolerance_m` how near the path's last waypoint the pelvis
  /// must come (none without a path). `events` must outlive the referee.
  Referee(const Scenario& scenario, double goal_tolerance_m, EventLog& events);

  /// A new episode: nothing judged yet.
  void Reset();

  /// A stop was commanded at t_s (the first one is recorded), or resumed.
  void StopCommanded(double t_s);
  void Resumed() { stop_pending_ = false; }

  /// The legs' events of the sample at t_s, before its state: a foot that
  /// landed where it cannot stand is a fall; a step refused is a fall under
  /// unsafe_steps: fall (unless the gait plans on its own map, or the step
  /// passes over level ground: the legs' own limits). The others are passed
  /// on to the event log. `ground_z_m` the ground the pelvis stands over (a
  /// fall without a place lands there).
  void LegEvents(std::vector<LocomotionEvent> events, double t_s, const RobotState& state, double ground_z_m);

  /// The sample at t_s after the strategy decided: standing, the goal, the clearance.
  void Judge(double t_s, const RobotState& state, double clearance_m);

  /// The contacts of the sample at t_s: each new one logged; the end of the
  /// episode under on_collision: stop.
  void Contacts(double t_s, const std::vector<BodyContact>& contacts);

  const RobotOutcome& robot() const { return outcome_; }
  /// The episode's outcome as summary.json states it: reached_goal, stopped
  /// (by its strategy, standing), collided, fell, refused (standing before an
  /// unsafe step its legs refused) or time_up (at `last_t_s`, the last sample's).
  EpisodeOutcome outcome(double last_t_s) const;

 private:
  void Fall(const std::string& reason, double t_s, const RobotState& state, double ground_z_m,
            const std::optional<Vec3>& p_W);
  void UpdateStanding(double t_s, bool stopped);

  bool stop_on_collision_ = false;  // on_collision: stop
  bool unsafe_steps_fall_ = false;  // unsafe_steps: fall
  bool own_map_ = false;            // the gait plans on the robot's own map (footholds: map)
  std::optional<Vec2> goal_m_;      // the path's last waypoint
  double goal_tolerance_m_ = 0;
  EventLog& events_;
  // the episode
  RobotOutcome outcome_;
  std::vector<BodyContact> contacts_before_;  // the last sample's
  bool stop_pending_ = false;             // a stop command not resumed since
  double walking_since_t_s_ = 0;          // when the robot last started walking
  double cannot_step_t_s_ = -std::numeric_limits<double>::infinity();  // the last cannot_step event
  std::string cannot_step_detail_;                                      // and its reason
};

}  // namespace proxsim
