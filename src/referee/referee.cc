#include "referee/referee.h"

#include <algorithm>
#include <cstdio>


namespace proxsim {

std::optional<OutcomeKind> OutcomeFromName(std::string_view name) {
  for (std::size_t i = 0; i < kOutcomeNames.size(); ++i)
    if (kOutcomeNames[i] == name) return static_cast<OutcomeKind>(i);
  return std::nullopt;
}

Referee::Referee(const Scenario& scenario, double goal_tolerance_m, EventLog& events) : events_(events) {
  if (const auto& robot = scenario.robot) {
    stop_on_collision_ = robot->on_collision == OnCollision::kStop;
    unsafe_steps_fall_ = robot->unsafe_steps == UnsafeSteps::kFall;
    own_map_ = robot->footholds == Footholds::kMap;
    // a path walked by the gait has a goal (a replayed trajectory has none)
    if (robot->trajectory_file.empty() && !robot->waypoints_m.empty()) {
      goal_m_ = robot->waypoints_m.back();
      goal_tolerance_m_ = goal_tolerance_m;
    }
  }
}

void Referee::Reset() {
  outcome_ = RobotOutcome{};
  contacts_before_.clear();
  stop_pending_ = false;
  walking_since_t_s_ = 0;
  cannot_step_t_s_ = -std::numeric_limits<double>::infinity();
  cannot_step_detail_.clear();
}

void Referee::StopCommanded(double t_s) {
  if (!outcome_.stop_requested) {
    outcome_.stop_requested = true;
    outcome_.stop_request_t_s = t_s;
  }
  stop_pending_ = true;
}

void Referee::LegEvents(std::vector<LocomotionEvent> events, double t_s, const RobotState& state, double ground_z_m) {
  // Whether a step the gait refuses is taken, and the robot falls
  // (unsafe_steps: fall), rather than stood before: never when the gait plans
  // on the robot's own map (footholds: map) — the refusal is then the robot's
  // own judgement of what it saw, and it stands.
  const bool unsafe_steps_fall = unsafe_steps_fall_ && !own_map_;
  std::string unsafe_step;
  for (LocomotionEvent& event : events) {
    // a foot that landed where it cannot stand (gait.footholds: map): the fall is the event
    if (event.event == "fall") {
      Fall(event.detail, t_s, state, ground_z_m, event.p_W);
      continue;
    }
    if (event.event == "cannot_step") {
      cannot_step_t_s_ = t_s;
      cannot_step_detail_ = event.detail;
      // under unsafe_steps: fall the step is taken, not refused: the fall is the event
      // (unless the gait plans on its own map: then the map said so, and the
      // robot stands; or the step passes over level ground: the legs' own limits)
      if (unsafe_steps_fall && !event.level_ground) {
        unsafe_step = event.detail;
        continue;
      }
    }
    events_.Log(std::move(event.event), std::move(event.detail));
  }
  if (!unsafe_step.empty()) Fall(unsafe_step, t_s, state, ground_z_m, std::nullopt);
}

void Referee::Fall(const std::string& reason, double t_s, const RobotState& state, double ground_z_m,
                   const std::optional<Vec3>& p_W) {
  if (outcome_.ended) return;
  outcome_.fell = outcome_.ended = true;
  // where: the gait's place for it (the foothold it missed), or else the
  // pelvis's point on the ground it stood on (a step the legs could not take)
  const Vec3 p_WP = state.X_WP.translation();
  outcome_.fall_p_W = p_W ? *p_W : Vec3(p_WP.x(), p_WP.y(), ground_z_m);
  outcome_.fall_reason = reason;
  outcome_.end_t_s = t_s;
  outcome_.end_detail = "fell: " + reason;
  events_.Log("fall", outcome_.end_detail);
}

void Referee::Judge(double t_s, const RobotState& state, double clearance_m) {
  UpdateStanding(t_s, state.stopped);
  if (goal_m_ && !outcome_.reached_goal && (state.X_WP.translation().head<2>() - *goal_m_).norm() <= goal_tolerance_m_) {
    outcome_.reached_goal = true;
    outcome_.reached_goal_t_s = t_s;
    char detail[160];
    std::snprintf(detail, sizeof detail, "pelvis within %.2f m of the last waypoint (%.2f, %.2f)", goal_tolerance_m_,
                  goal_m_->x(), goal_m_->y());
    events_.Log("goal_reached", detail);
  }
  // the truth, for the summary only
  if (clearance_m < outcome_.min_clearance_m) {
    outcome_.min_clearance_m = clearance_m;
    outcome_.min_clearance_t_s = t_s;
  }
}

void Referee::UpdateStanding(double t_s, bool stopped) {
  if (!stopped) {
    if (outcome_.stopped) walking_since_t_s_ = t_s;
    outcome_.stopped = false;
    outcome_.stop_reason.clear();
    return;
  }
  if (outcome_.stopped) return;  // standing since an earlier sample
  outcome_.stopped = true;
  outcome_.stop_t_s = t_s;
  outcome_.stop_reason = stop_pending_                           ? "strategy"
                         : cannot_step_t_s_ >= walking_since_t_s_ ? (own_map_ ? "own_map" : "cannot_step")
                                                                  : "end_of_path";
  if (stop_pending_) {
    char detail[160];
    std::snprintf(detail, sizeof detail, "standing, both feet down, after the stop commanded at t = %.2f s",
                  outcome_.stop_request_t_s);
    events_.Log("stopped", detail);
  }
}

void Referee::Contacts(double t_s, const std::vector<BodyContact>& contacts) {
  const auto same = [](const BodyContact& a, const BodyContact& b) {
    return a.link == b.link && a.object == b.object && a.self == b.self;
  };
  for (const BodyContact& contact : contacts) {
    // a contact that lasts is one collision, logged when it begins
    if (std::any_of(contacts_before_.begin(), contacts_before_.end(),
                    [&](const BodyContact& c) { return same(c, contact); }))
      continue;
    RobotOutcome::Collision collision{.t_s = t_s,
                                      .link = contact.link,
                                      .object = contact.object,
                                      .self = contact.self,
                                      .depth_m = contact.depth_m,
                                      .p_W = contact.p_W};
    char detail[256];
    std::snprintf(detail, sizeof detail, "%s %s %s, %.0f mm deep at (%.2f, %.2f, %.2f)", collision.link.c_str(),
                  collision.self ? "touched its own" : "struck", collision.object.c_str(), 1000 * contact.depth_m,
                  contact.p_W.x(), contact.p_W.y(), contact.p_W.z());
    events_.Log("collision", detail);
    outcome_.collisions.push_back(std::move(collision));
    if (stop_on_collision_ && !outcome_.ended) {
      outcome_.collided = outcome_.ended = true;
      outcome_.end_t_s = t_s;
      outcome_.end_detail = std::string("collided: ") + detail;
    }
  }
  contacts_before_ = contacts;
}

EpisodeOutcome Referee::outcome(double last_t_s) const {
  // the goal ends the episode's story: nothing after it (a collision, the
  // gait's last step past a limit) changes its outcome
  const auto after_goal = [&](double t_s) { return outcome_.reached_goal && t_s > outcome_.reached_goal_t_s; };
  const bool collided_first = !outcome_.collisions.empty() && !after_goal(outcome_.collisions.front().t_s);
  const bool fell_first = outcome_.fell && !after_goal(outcome_.end_t_s);
  if (!collided_first && !fell_first && outcome_.reached_goal)
    return {OutcomeKind::kReachedGoal, outcome_.reached_goal_t_s, "reached the path's last waypoint"};
  if (outcome_.collided) return {OutcomeKind::kCollided, outcome_.end_t_s, outcome_.end_detail};
  // under on_collision: continue the walk went on, but the episode still collided
  if (!outcome_.collisions.empty()) {
    const RobotOutcome::Collision& first = outcome_.collisions.front();
    return {OutcomeKind::kCollided, first.t_s,
            "collided: " + first.link + (first.self ? " touched its own " : " struck ") + first.object +
                " (on_collision: continue; " + std::to_string(outcome_.collisions.size()) + " collisions in all)"};
  }
  if (outcome_.fell) return {OutcomeKind::kFell, outcome_.end_t_s, outcome_.end_detail};
  if (outcome_.reached_goal)
    return {OutcomeKind::kReachedGoal, outcome_.reached_goal_t_s, "reached the path's last waypoint"};
  if (outcome_.stopped && outcome_.stop_reason == "strategy")
    return {OutcomeKind::kStopped, outcome_.stop_t_s, "stopped by its strategy, standing"};
  if (outcome_.stopped && outcome_.stop_reason == "own_map")
    return {OutcomeKind::kStopped, outcome_.stop_t_s,
            "standing before a step its own map shows it cannot take (footholds: map): " + cannot_step_detail_};
  if (outcome_.stopped && outcome_.stop_reason == "cannot_step")
    return {OutcomeKind::kRefused, outcome_.stop_t_s, "standing before a step its legs cannot take (unsafe_steps: refuse)"};
  return {OutcomeKind::kTimeUp, last_t_s, "the episode's time ran out"};
}

}  // namespace proxsim
