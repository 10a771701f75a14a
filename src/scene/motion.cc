#include "scene/motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace proxsim {

namespace {

/// The waypoints walked in one period of the mode, without a copy (a moving
/// object's pose is asked for every sample): loop closes the polygon,
/// back_and_forth appends the way back, once is the polyline itself.
class PeriodPoints {
 public:
  explicit PeriodPoints(const Motion& motion) : points_(motion.waypoints_m) {
    const std::size_t n = points_.size();
    size_ = n;
    if (motion.mode == MotionMode::kLoop && (points_.back() - points_.front()).norm() > 0) size_ = n + 1;
    if (motion.mode == MotionMode::kBackAndForth) size_ = 2 * n - 1;
  }
  std::size_t size() const { return size_; }
  const Vec2& front() const { return points_.front(); }
  const Vec2& operator[](std::size_t i) const {
    const std::size_t n = points_.size();
    if (i < n) return points_[i];
    return size_ == n + 1 ? points_.front() : points_[2 * n - 2 - i];  // the loop's closing point, or the way back
  }

 private:
  const std::vector<Vec2>& points_;
  std::size_t size_ = 0;
};

/// The point at arc length u along `points` and the direction of its segment.
void PointAlong(const PeriodPoints& points, double u, Vec2* p, Vec2* direction) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Vec2 segment = points[i + 1] - points[i];
    const double length_m = segment.norm();
    // the last segment takes whatever is left (rounding at the very end)
    if (u < length_m || i + 2 == points.size()) {
      const double f = length_m > 0 ? std::clamp(u / length_m, 0.0, 1.0) : 0.0;
      *p = points[i] + f * segment;
      *direction = length_m > 0 ? Vec2(segment / length_m) : Vec2::UnitX();
      return;
    }
    u -= length_m;
  }
  *p = points.front();
  *direction = Vec2::UnitX();
}

double PathLength_m(const PeriodPoints& points) {
  double length_m = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) length_m += (points[i + 1] - points[i]).norm();
  return length_m;
}

Pose FrameAt(const Vec3& p_WM, double yaw_rad) {
  Pose X_WM = Pose::Identity();
  X_WM.translation() = p_WM;
  X_WM.linear() = Eigen::AngleAxisd(yaw_rad, Vec3::UnitZ()).toRotationMatrix();
  return X_WM;
}

MotionFrame WaypointsFrame(const Motion& motion, double t_s) {
  const PeriodPoints points(motion);
  const double period_m = PathLength_m(points);
  const double s_m = motion.speed_m_s * std::max(0.0, t_s - motion.start_s);
  MotionFrame frame;
  double u_m = s_m;
  if (motion.mode == MotionMode::kOnce) {
    u_m = std::min(s_m, period_m);
    frame.travelled_m = u_m;
  } else {
    u_m = std::fmod(s_m, period_m);
    frame.travelled_m = s_m;
  }
  Vec2 p, direction;
  PointAlong(points, u_m, &p, &direction);
  frame.X_WM = FrameAt(Vec3(p.x(), p.y(), 0), std::atan2(direction.y(), direction.x()));
  return frame;
}

MotionFrame TrajectoryFrame(const Motion& motion, double t_s) {
  const std::vector<TrajectoryRow>& rows = motion.trajectory;
  MotionFrame frame;
  // the distance travelled up to each row is summed as the segments pass
  double travelled_m = 0;
  if (t_s <= rows.front().t_s) {
    frame.X_WM = FrameAt(rows.front().p_WM, rows.front().yaw_rad);
    return frame;
  }
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
    const TrajectoryRow& a = rows[i];
    const TrajectoryRow& b = rows[i + 1];
    const double step_m = (b.p_WM - a.p_WM).norm();
    if (t_s < b.t_s) {
      const double f = (t_s - a.t_s) / (b.t_s - a.t_s);
      // yaw along the shorter way round
      const double dyaw = std::remainder(b.yaw_rad - a.yaw_rad, 2 * kPi);
      frame.X_WM = FrameAt(a.p_WM + f * (b.p_WM - a.p_WM), a.yaw_rad + f * dyaw);
      frame.travelled_m = travelled_m + f * step_m;
      return frame;
    }
    travelled_m += step_m;
  }
  frame.X_WM = FrameAt(rows.back().p_WM, rows.back().yaw_rad);
  frame.travelled_m = travelled_m;
  return frame;
}

}  // namespace

const std::vector<std::string>& MotionModeNames() {
  static const std::vector<std::string> names = {"loop", "back_and_forth", "once"};
  return names;
}

MotionFrame MotionFrameAt(const Motion& motion, double t_s) {
  switch (motion.kind) {
    case Motion::Kind::kWaypoints: return WaypointsFrame(motion, t_s);
    case Motion::Kind::kTrajectory: return TrajectoryFrame(motion, t_s);
    case Motion::Kind::kVelocity: break;
  }
  MotionFrame frame;
  frame.X_WM.translation() = motion.velocity_m_s * t_s;
  frame.travelled_m = motion.velocity_m_s.norm() * std::abs(t_s);
  return frame;
}

Pose MotionPoseAt(const Motion& motion, double t_s) {
  const MotionFrame frame = MotionFrameAt(motion, t_s);
  if (motion.swing.amplitude_rad == 0) return frame.X_WM * motion.X_MO;
  // the swing: a pitch about the pivot, its angle following the distance travelled
  const Swing& swing = motion.swing;
  const double angle_rad =
      swing.amplitude_rad * std::sin(2 * kPi * frame.travelled_m / swing.cycle_m + swing.phase_rad);
  Pose swing_M = Pose::Identity();
  swing_M.translation() = swing.pivot_M;
  swing_M.linear() = Eigen::AngleAxisd(angle_rad, swing.axis_M).toRotationMatrix();
  swing_M.translate(-swing.pivot_M);
  return frame.X_WM * swing_M * motion.X_MO;
}

Vec3 MotionPointVelocity_W(const Motion& motion, double t_s, const Vec3& p_W) {
  constexpr double kHalfStep_s = 5e-4;
  const Vec3 p_O = MotionPoseAt(motion, t_s).inverse() * p_W;
  return (MotionPoseAt(motion, t_s + kHalfStep_s) * p_O - MotionPoseAt(motion, t_s - kHalfStep_s) * p_O) /
         (2 * kHalfStep_s);
}

std::vector<std::string> MotionProblems(const Motion& motion) {
  std::vector<std::string> problems;
  char text[200];
  if (motion.kind == Motion::Kind::kWaypoints) {
    if (motion.waypoints_m.size() < 2) problems.push_back("expected at least two waypoints [x, y]");
    for (std::size_t i = 0; i + 1 < motion.waypoints_m.size(); ++i) {
      if ((motion.waypoints_m[i + 1] - motion.waypoints_m[i]).norm() > 0) continue;
      std::snprintf(text, sizeof text, "waypoints %zu and %zu are the same point: nothing to face", i,
                    i + 1);
      problems.emplace_back(text);
    }
  }
  if (motion.kind == Motion::Kind::kTrajectory) {
    if (motion.trajectory.size() < 2) problems.push_back("expected at least two rows");
    for (std::size_t i = 0; i + 1 < motion.trajectory.size(); ++i) {
      if (motion.trajectory[i + 1].t_s > motion.trajectory[i].t_s) continue;
      std::snprintf(text, sizeof text, "t_s must increase from row to row; data row %zu (t_s = %g) follows t_s = %g",
                    i + 2, motion.trajectory[i + 1].t_s, motion.trajectory[i].t_s);
      problems.emplace_back(text);
      break;
    }
  }
  return problems;
}

}  // namespace proxsim
