#include "gait/leg_kinematics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <queue>
#include <tuple>

#include "core/input_error.h"
#include "core/nearest_key.h"
#include "gait/shank_clearance.h"
#include "scene/shape_points.h"

namespace proxsim {

namespace {

// Points this close above the lowest one make up the sole: a flat sole
// meshed or modelled within 2 mm is one plane.
constexpr double kSoleBand_m = 0.002;
// Shortest thigh or shank the planar chain accepts.
constexpr double kMinSegment_m = 0.01;
// Largest difference between the legs' lengths, and the most any other link
// may hang below the soles at the reference pose.
constexpr double kReachTolerance_m = 0.01;
// A knee bent this far either way from the reference pose tells which way its limits let it bend, rad.
constexpr double kKneeBendProbe_rad = 0.3;

const char* SideName(Side s) { return s == Side::kLeft ? "left" : "right"; }

// Every link from `link` down (itself first), breadth first.
std::vector<int> Subtree(const RobotModel& model, int link) {
  std::vector<int> links;
  std::queue<int> todo;
  todo.push(link);
  while (!todo.empty()) {
    const int l = todo.front();
    todo.pop();
    links.push_back(l);
    for (const int j : model.link(l).child_joints) todo.push(model.joint(j).child_link);
  }
  return links;
}

// The outline points of a link's geometry, in P at the reference pose.
void AddLinkPoints_P(const RobotModel& model, int link, const std::vector<Pose>& X_PL, std::vector<Vec3>* points) {
  for (const LinkShape& shape : model.link(link).shapes) {
    const Pose X_PO = X_PL[link] * shape.X_LO;
    for (const Vec3& p_O : ShapeOutlinePoints_O(shape.shape)) points->push_back(X_PO * p_O);
  }
}

// Joints from the root to `link`, parents first.
std::vector<int> ChainTo(const RobotModel& model, int link) {
  std::vector<int> chain;
  for (int l = link; model.link(l).parent_joint >= 0; l = model.joint(model.link(l).parent_joint).parent_link)
    chain.push_back(model.link(l).parent_joint);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// A segment's angle from the downward vertical (lower end forward +) and length, in the sagittal plane.
std::pair<double, double> SagittalSegment(const Vec3& upper, const Vec3& lower) {
  const Vec2xz d(lower.x() - upper.x(), lower.z() - upper.z());
  return {std::atan2(d.x(), -d.y()), d.norm()};
}

}  // namespace

std::array<LegNames, 2> BuiltinBipedLegs() {
  return {LegNames{"left_hip_pitch", "left_knee_pitch", "left_ankle_pitch", "left_foot"},
          LegNames{"right_hip_pitch", "right_knee_pitch", "right_ankle_pitch", "right_foot"}};
}

BipedLegs::BipedLegs(const RobotModel& model) : BipedLegs(model, std::nullopt, std::vector<double>(model.joint_count(), 0.0)) {}

BipedLegs::BipedLegs(const RobotModel& m, const std::optional<std::array<LegNames, 2>>& given,
                     std::span<const double> q_reference)
    : model_(m), q_reference_(q_reference.begin(), q_reference.end()) {
  const std::string& source = m.source();
  const std::array<LegNames, 2> names = given.value_or(BuiltinBipedLegs());
  std::vector<std::string> problems;

  // without a map, a robot that is not built like the built-in biped gets one message
  if (!given) {
    std::string missing;
    for (const LegNames& leg : names) {
      for (const std::string& joint : {leg.hip, leg.knee, leg.ankle})
        if (m.JointIndex(joint) < 0) missing += (missing.empty() ? "" : ", ") + joint;
      if (m.LinkIndex(leg.foot) < 0) missing += (missing.empty() ? "" : ", ") + leg.foot;
    }
    if (!missing.empty()) {
      throw InputError(source + ": robot.legs is not given and the robot lacks the built-in biped's " + missing +
                       "; map the gait onto its legs: robot.legs: {left: {hip: JOINT, knee: JOINT, ankle: JOINT, "
                       "foot: LINK}, right: {...}}");
    }
  }
  std::vector<std::string> joint_names, link_names;
  for (int j = 0; j < m.joint_count(); ++j) joint_names.push_back(m.joint_name(j));
  for (int l = 0; l < m.link_count(); ++l) link_names.push_back(m.link_name(l));
  const auto unknown = [&](const std::string& key, const std::string& what, const std::string& name,
                           const std::vector<std::string>& candidates) {
    const auto nearest = NearestKey(name, candidates);
    problems.push_back(source + ": " + key + ": no " + what + " '" + name + "' in the URDF" +
                       (nearest ? " (did you mean '" + *nearest + "'?)" : ""));
  };

  const std::vector<Pose> X_PL = m.ForwardKinematics(Pose::Identity(), q_reference_);
  std::vector<int> feet_subtrees;
  double lowest_sole_P = std::numeric_limits<double>::infinity();
  bool legs_ok = true;
  for (const Side side : {Side::kLeft, Side::kRight}) {
    const LegNames& name = names[static_cast<int>(side)];
    const std::string key = std::string("robot.legs.") + SideName(side);
    LegGeometry& g = legs_[static_cast<int>(side)];
    const std::size_t problems_before = problems.size();

    // the names: three revolute joints and a link
    int* const joint_of[3] = {&g.hip_joint, &g.knee_joint, &g.ankle_joint};
    const std::string* const joint_name[3] = {&name.hip, &name.knee, &name.ankle};
    const char* const joint_key[3] = {"hip", "knee", "ankle"};
    for (int k = 0; k < 3; ++k) {
      *joint_of[k] = m.JointIndex(*joint_name[k]);
      if (*joint_of[k] < 0) {
        unknown(key + "." + joint_key[k], "joint", *joint_name[k], joint_names);
        continue;
      }
      const JointType type = m.joint(*joint_of[k]).type;
      if (type != JointType::kRevolute && type != JointType::kContinuous)
        problems.push_back(source + ": " + key + "." + joint_key[k] + ": joint '" + *joint_name[k] +
                           "' is not revolute; the gait turns the leg's pitch joints");
    }
    g.foot_link = m.LinkIndex(name.foot);
    if (g.foot_link < 0) unknown(key + ".foot", "link", name.foot, link_names);
    if (problems.size() > problems_before) {
      legs_ok = false;
      continue;
    }

    // one chain from the root: hip, knee, ankle, foot in that order
    chain_[static_cast<int>(side)] = ChainTo(m, g.foot_link);
    const std::vector<int>& chain = chain_[static_cast<int>(side)];
    std::ptrdiff_t at[3];
    for (int k = 0; k < 3; ++k) at[k] = std::find(chain.begin(), chain.end(), *joint_of[k]) - chain.begin();
    for (int k = 0; k < 3; ++k) {
      if (at[k] == static_cast<std::ptrdiff_t>(chain.size())) {
        problems.push_back(source + ": " + key + "." + joint_key[k] + ": joint '" + *joint_name[k] +
                           "' is not on the chain from the root link to the foot '" + name.foot + "'");
      }
    }
    if (problems.size() == problems_before && !(at[0] < at[1] && at[1] < at[2])) {
      problems.push_back(source + ": " + key + ": the chain from the root to the foot must pass the hip, then the "
                         "knee, then the ankle; it passes '" + *joint_name[0] + "' at joint " + std::to_string(at[0] + 1) +
                         ", '" + *joint_name[1] + "' at " + std::to_string(at[1] + 1) + ", '" + *joint_name[2] +
                         "' at " + std::to_string(at[2] + 1));
    }

    // the pitch axes, at the reference pose: within the tolerance of ±y_P
    double* const sign_of[3] = {&g.hip_sign, &g.knee_sign, &g.ankle_sign};
    Vec3 p_P[3];
    for (int k = 0; k < 3; ++k) {
      const RobotJoint& joint = m.joint(*joint_of[k]);
      const Pose& X_PJ = X_PL[joint.child_link];  // the child frame is the joint frame moved by q
      const Vec3 axis_P = X_PJ.linear() * joint.axis_J;
      p_P[k] = X_PJ.translation();
      *sign_of[k] = axis_P.y() >= 0 ? 1.0 : -1.0;
      const double tilt_deg = RadToDeg(std::acos(std::min(1.0, std::abs(axis_P.y()))));
      if (tilt_deg > kMaxPitchAxisTilt_deg) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "'s axis is %.1f° off the sagittal normal (the root link's y axis) at the reference pose; "
                      "a pitch axis must be within %.0f°",
                      tilt_deg, kMaxPitchAxisTilt_deg);
        problems.push_back(source + ": " + key + "." + joint_key[k] + ": joint '" + *joint_name[k] + "'" + text);
      }
    }
    g.p_PH = p_P[0];
    std::tie(g.thigh0_rad, g.thigh_m) = SagittalSegment(p_P[0], p_P[1]);
    std::tie(g.shank0_rad, g.shank_m) = SagittalSegment(p_P[1], p_P[2]);
    // the knee's bend: the way its limits allow (a continuous or unlimited
    // joint, or limits that allow neither, keep the human one: flexion)
    {
      const RobotJoint& knee = m.joint(g.knee_joint);
      const auto allows = [&](double flexion) {
        const double q = g.knee_sign * (flexion - (g.thigh0_rad - g.shank0_rad));
        return q >= knee.lower && q <= knee.upper;
      };
      if (knee.type == JointType::kRevolute && knee.lower < knee.upper && !allows(kKneeBendProbe_rad) &&
          allows(-kKneeBendProbe_rad))
        g.knee_bend = -1;
    }
    if (g.thigh_m < kMinSegment_m || g.shank_m < kMinSegment_m) {
      char text[200];
      std::snprintf(text, sizeof text, ": the legs cannot reach the ground: thigh %.3f m and shank %.3f m in the "
                    "sagittal plane; each must be at least %.2f m", g.thigh_m, g.shank_m, kMinSegment_m);
      problems.push_back(source + ": " + key + text);
    }

    // the shank: the links below the knee joint and above the ankle joint,
    // in its own frame (a rotation keeps the hull convex and counter-clockwise)
    {
      const std::vector<int> below_ankle = Subtree(m, m.joint(g.ankle_joint).child_link);
      std::vector<Vec3> points_P;
      for (const int link : Subtree(m, m.joint(g.knee_joint).child_link))
        if (std::find(below_ankle.begin(), below_ankle.end(), link) == below_ankle.end())
          AddLinkPoints_P(m, link, X_PL, &points_P);
      std::vector<Vec2xz> points_S;
      for (const Vec3& p : points_P)
        points_S.push_back(RotateSagittal(-g.shank0_rad, Vec2xz(p.x() - p_P[1].x(), p.z() - p_P[1].z())));
      g.shank_hull_S = ConvexHull2(std::move(points_S));
    }

    // the sole: the lowest points of the foot and what hangs from it
    const std::vector<int> foot_links = Subtree(m, g.foot_link);
    feet_subtrees.insert(feet_subtrees.end(), foot_links.begin(), foot_links.end());
    std::vector<Vec3> points_P;
    for (const int link : foot_links) AddLinkPoints_P(m, link, X_PL, &points_P);
    if (points_P.empty()) {
      problems.push_back(source + ": " + key + ".foot: link '" + name.foot +
                         "' (and the links below it) has no geometry; the gait stands on its lowest points");
      legs_ok = false;
      continue;
    }
    // a foot pitched at joint zero (legs.*.ankle_zero_deg) is read turned flat about the ankle joint
    const Vec3& p_PA = p_P[2];
    const auto turn_about_ankle = [&](const Vec3& p, double angle_rad) {
      const Vec2xz v = RotateSagittal(angle_rad, Vec2xz(p.x() - p_PA.x(), p.z() - p_PA.z()));
      return Vec3(p_PA.x() + v.x(), p.y(), p_PA.z() + v.y());
    };
    const std::vector<Vec3> raw_points_P = points_P;
    double lowest = 0, heel = 0, toe = 0;
    // the sole read with the foot turned flat by foot0: its lowest points, their ends and the faces there
    const auto measure_sole = [&](double foot0_rad) {
      g.foot0_rad = foot0_rad;
      points_P = raw_points_P;
      if (foot0_rad != 0.0)
        for (Vec3& p : points_P) p = turn_about_ankle(p, -foot0_rad);
      lowest = std::numeric_limits<double>::infinity();
      for (const Vec3& p : points_P) lowest = std::min(lowest, p.z());
      heel = std::numeric_limits<double>::infinity(), toe = -heel;
      double y_min = heel, y_max = -heel;
      for (const Vec3& p : points_P) {
        if (p.z() > lowest + kSoleBand_m) continue;
        heel = std::min(heel, p.x());
        toe = std::max(toe, p.x());
        y_min = std::min(y_min, p.y());
        y_max = std::max(y_max, p.y());
      }
      // the faces at either end of the sole (a pitched foot's front face leads it into a riser)
      g.toe_top_m = g.heel_top_m = 0;
      for (const Vec3& p : points_P) {
        if (p.x() >= toe - kSoleBand_m) g.toe_top_m = std::max(g.toe_top_m, p.z() - lowest);
        if (p.x() <= heel + kSoleBand_m) g.heel_top_m = std::max(g.heel_top_m, p.z() - lowest);
      }
      g.sole_z_m = lowest - p_PA.z();
      g.heel_x_m = heel - p_PA.x();
      g.toe_x_m = toe - p_PA.x();
      g.sole_y_m = 0.5 * (y_min + y_max);
      g.half_width_m = 0.5 * (y_max - y_min);
      return g.heel_x_m < 0 && g.toe_x_m > 0 && g.sole_z_m < 0;
    };
    // the pitch at which the foot's lowest points spread longest along x: where its sole lies flat
    const auto flattest_rad = [&]() {
      double best_extent_m = -1, flat_from = 0, flat_to = 0;
      for (int tenth = -450; tenth <= 450; ++tenth) {
        const double psi = DegToRad(0.1 * tenth);
        double low = std::numeric_limits<double>::infinity(), back = low, front = -low;
        for (const Vec3& p : raw_points_P) low = std::min(low, turn_about_ankle(p, -psi).z());
        for (const Vec3& p : raw_points_P) {
          const Vec3 q = turn_about_ankle(p, -psi);
          if (q.z() > low + kSoleBand_m) continue;
          back = std::min(back, q.x());
          front = std::max(front, q.x());
        }
        const double extent_m = front - back;
        if (extent_m > best_extent_m + 1e-3) {
          best_extent_m = extent_m;
          flat_from = flat_to = 0.1 * tenth;
        } else if (extent_m >= best_extent_m - 1e-3) {
          flat_to = 0.1 * tenth;  // the plateau of the longest sole: its middle is the flat pitch
        }
      }
      return DegToRad(0.5 * (flat_from + flat_to));
    };
    bool sole_ok = measure_sole(name.ankle_zero_rad);
    // not given, and not flat at joint zero: the foot is read at the pitch its geometry lies flattest at
    if (!sole_ok && !name.ankle_zero_given) sole_ok = measure_sole(flattest_rad());
    if (!sole_ok) {
      const double given_rad = name.ankle_zero_rad, flat_rad = flattest_rad();
      measure_sole(given_rad);
      char text[600];
      std::snprintf(text, sizeof text,
                    "' has its sole (its lowest points, within %.0f mm) from %.3f to %.3f m along x and %.3f m "
                    "below the ankle joint; the sole must reach behind and in front of the ankle, below it "
                    "(a foot pitched at joint zero is read flat when %s.ankle_zero_deg gives its pitch there, toe up "
                    "positive: its geometry lies flattest at %.1f deg)",
                    1e3 * kSoleBand_m, g.heel_x_m, g.toe_x_m, -g.sole_z_m, key.c_str(), RadToDeg(flat_rad));
      problems.push_back(source + ": " + key + ".foot: link '" + name.foot + text);
    }
    lowest_sole_P = std::min(lowest_sole_P, lowest);
    // the foot points in the foot link's own frame
    const Pose X_LP = X_PL[g.foot_link].inverse();
    // (turned back by ψ0: the material points, where they are at the reference pose)
    g.p_L_heel = X_LP * turn_about_ankle(Vec3(heel, g.sole_y_m, lowest), g.foot0_rad);
    g.p_L_sole = X_LP * turn_about_ankle(Vec3(p_PA.x(), g.sole_y_m, lowest), g.foot0_rad);
    g.p_L_toe = X_LP * turn_about_ankle(Vec3(toe, g.sole_y_m, lowest), g.foot0_rad);
    g.up_L = X_LP.linear() * Vec3(-std::sin(g.foot0_rad), 0.0, std::cos(g.foot0_rad));
  }
  // two legs, not one mapped twice (no joint or foot shared: one leg walked as both passed validation),
  // and not swapped
  if (legs_ok) {
    const LegGeometry &left = legs_[0], &right = legs_[1];
    const int left_joints[3] = {left.hip_joint, left.knee_joint, left.ankle_joint};
    const int right_joints[3] = {right.hip_joint, right.knee_joint, right.ankle_joint};
    const char* const joint_key[3] = {"hip", "knee", "ankle"};
    for (int k = 0; k < 3; ++k) {
      if (std::find(std::begin(left_joints), std::end(left_joints), right_joints[k]) != std::end(left_joints))
        problems.push_back(source + ": robot.legs.right." + joint_key[k] + ": joint '" +
                           m.joint(right_joints[k]).name + "' is also the left leg's; each leg needs joints of its own");
    }
    if (left.foot_link == right.foot_link)
      problems.push_back(source + ": robot.legs.right.foot: link '" + m.link_name(right.foot_link) +
                         "' is also the left leg's foot; each leg needs a foot of its own");
    // left is +y of the root link (REP-103): a left leg whose hip lies right of the other's is a swapped map
    if (left.hip_joint != right.hip_joint && left.p_PH.y() < right.p_PH.y()) {
      char text[300];
      std::snprintf(text, sizeof text, " lies right of the right leg's hip (y = %.3f m against %.3f m in the root "
                    "link's frame, +y to the left): left and right are swapped",
                    left.p_PH.y(), right.p_PH.y());
      problems.push_back(source + ": robot.legs.left.hip: joint '" + m.joint(left.hip_joint).name + "'" + text +
                         " (the right leg's hip is '" + m.joint(right.hip_joint).name + "')");
    }
  }
  if (!problems.empty() || !legs_ok) throw InputError(problems);

  // standing straight: both legs must reach the floor, nothing else below it
  const LegAnglesRad straight;
  double standing[2];
  for (const Side side : {Side::kLeft, Side::kRight}) {
    LegGeometry& g = legs_[static_cast<int>(side)];
    standing[static_cast<int>(side)] = -Point(side, straight, FootPoint::kMid).y();
    g.leg_length_m = g.p_PH.z() + standing[static_cast<int>(side)];
  }
  standing_height_m_ = std::min(standing[0], standing[1]);
  if (std::abs(legs_[0].leg_length_m - legs_[1].leg_length_m) > kReachTolerance_m) {
    char text[300];
    std::snprintf(text, sizeof text,
                  ": the legs cannot both reach the ground: standing straight, the left sole is %.3f m and the right "
                  "%.3f m below the pelvis (they may differ by %.0f mm at most)",
                  standing[0], standing[1], 1e3 * kReachTolerance_m);
    problems.push_back(source + ": robot.legs" + text);
  }
  std::sort(feet_subtrees.begin(), feet_subtrees.end());
  for (int link = 0; link < m.link_count(); ++link) {
    if (std::binary_search(feet_subtrees.begin(), feet_subtrees.end(), link)) continue;
    std::vector<Vec3> points_P;
    AddLinkPoints_P(m, link, X_PL, &points_P);
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& p : points_P) lowest = std::min(lowest, p.z());
    if (lowest < lowest_sole_P - kReachTolerance_m) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "' hangs %.3f m below the soles at the reference pose, so the feet cannot reach the ground "
                    "(hold its joints with robot.joints_deg, or map the legs to the lowest links)",
                    lowest_sole_P - lowest);
      problems.push_back(source + ": robot.legs: link '" + m.link_name(link) + text);
    }
  }
  if (!problems.empty()) throw InputError(problems);
}

Vec2xz BipedLegs::Ankle(Side s, const LegAnglesRad& a) const {
  const LegGeometry& g = leg(s);
  const Vec2xz hip(g.p_PH.x(), g.p_PH.z());
  return hip + RotateSagittal(a.hip, {0, -g.thigh_m}) + RotateSagittal(a.hip - a.knee, {0, -g.shank_m});
}

std::vector<Vec2xz> BipedLegs::ShankHull(Side s, const LegAnglesRad& a) const {
  const LegGeometry& g = leg(s);
  const Vec2xz knee = Vec2xz(g.p_PH.x(), g.p_PH.z()) + RotateSagittal(a.hip, {0, -g.thigh_m});
  std::vector<Vec2xz> hull;
  hull.reserve(g.shank_hull_S.size());
  for (const Vec2xz& p_S : g.shank_hull_S) hull.push_back(knee + RotateSagittal(a.hip - a.knee, p_S));
  return hull;
}

Vec2xz BipedLegs::FootOffset(Side s, FootPoint which) const {
  const LegGeometry& g = leg(s);
  switch (which) {
    case FootPoint::kHeel: return {g.heel_x_m, g.sole_z_m};
    case FootPoint::kToe: return {g.toe_x_m, g.sole_z_m};
    case FootPoint::kMid: break;
  }
  return {0, g.sole_z_m};
}

Vec2xz BipedLegs::Point(Side s, const LegAnglesRad& a, FootPoint which) const {
  return Ankle(s, a) + RotateSagittal(a.pitch, FootOffset(s, which));
}

std::array<Vec2xz, 2> BipedLegs::HeelAndToe(Side s, const LegAnglesRad& a) const {
  const Vec2xz ankle = Ankle(s, a);
  // (the pitch's cosine and sine taken once for both points)
  const double c = std::cos(a.pitch), sn = std::sin(a.pitch);
  return {ankle + RotateSagittal(c, sn, FootOffset(s, FootPoint::kHeel)),
          ankle + RotateSagittal(c, sn, FootOffset(s, FootPoint::kToe))};
}

double BipedLegs::LowestSoleZ(Side s, const LegAnglesRad& a) const {
  const std::array<Vec2xz, 2> heel_toe = HeelAndToe(s, a);
  return std::min(heel_toe[0].y(), heel_toe[1].y());
}

LegAnglesRad BipedLegs::SolveAnkle(Side s, const Vec2xz& p_PA, double pitch) const {
  const LegGeometry& g = leg(s);
  const Vec2xz d = p_PA - Vec2xz(g.p_PH.x(), g.p_PH.z());
  const double lt = g.thigh_m, ls = g.shank_m;
  const double r = std::clamp(d.norm(), std::abs(lt - ls) + 1e-9, lt + ls);
  // law of cosines: r² = lt² + ls² + 2·lt·ls·cos(knee)
  const double cos_knee = std::clamp((r * r - lt * lt - ls * ls) / (2 * lt * ls), -1.0, 1.0);
  LegAnglesRad a;
  a.knee = g.knee_bend * std::acos(cos_knee);
  const double toward = std::atan2(d.x(), -d.y());  // hip→ankle line from the downward vertical
  a.hip = toward + std::atan2(ls * std::sin(a.knee), lt + ls * std::cos(a.knee));
  a.pitch = pitch;
  return a;
}

LegAnglesRad BipedLegs::PitchWithinAnkleLimits(Side s, const LegAnglesRad& a, double margin_rad) const {
  const LegGeometry& g = leg(s);
  const RobotJoint& ankle = model_.joint(g.ankle_joint);
  if (ankle.type != JointType::kRevolute || !(ankle.lower + 2 * margin_rad < ankle.upper)) return a;
  // q_ankle = s_a·(θS − θS0 − (ψ − ψ0)): the pitches at the two limits
  const double shank = (a.hip - a.knee) - g.shank0_rad + g.foot0_rad;
  const double at_lower = shank - (ankle.lower + margin_rad) / g.ankle_sign,
               at_upper = shank - (ankle.upper - margin_rad) / g.ankle_sign;
  LegAnglesRad out = a;
  out.pitch = std::clamp(a.pitch, std::min(at_lower, at_upper), std::max(at_lower, at_upper));
  return out;
}

Pose BipedLegs::FootPose_P(Side s, const LegAnglesRad& a) const {
  const LegGeometry& g = leg(s);
  const std::array<double, 3> v = JointValues(s, a);
  Pose X_PL = Pose::Identity();
  for (const int j : chain_[static_cast<int>(s)]) {
    double q = q_reference_[j];
    if (j == g.hip_joint) q = v[0];
    if (j == g.knee_joint) q = v[1];
    if (j == g.ankle_joint) q = v[2];
    X_PL = X_PL * model_.JointTransform(j, q);
  }
  return X_PL;
}

std::string BipedLegs::Fingerprint() const {
  std::string bytes;
  const auto put = [&bytes](const auto& value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  const auto put_vec = [&put](const Vec3& v) {
    for (int i = 0; i < 3; ++i) put(v[i]);
  };
  for (int s = 0; s < 2; ++s) {
    const LegGeometry& g = legs_[s];
    for (const int i : {g.hip_joint, g.knee_joint, g.ankle_joint, g.foot_link}) put(i);
    for (const double d : {g.hip_sign, g.knee_sign, g.ankle_sign, g.thigh0_rad, g.shank0_rad, g.thigh_m, g.shank_m,
                           g.heel_x_m, g.toe_x_m, g.sole_z_m, g.sole_y_m, g.half_width_m, g.toe_top_m, g.heel_top_m,
                           g.leg_length_m, g.knee_bend})
      put(d);
    for (const Vec3& v : {g.p_PH, g.p_L_heel, g.p_L_sole, g.p_L_toe}) put_vec(v);
    put(chain_[s].size());
    for (const int j : chain_[s]) {
      const RobotJoint& joint = model_.joint(j);
      put(j);
      put(joint.type);
      for (int k = 0; k < 16; ++k) put(joint.X_PJ.matrix().data()[k]);
      put_vec(joint.axis_J);
      for (const double d : {joint.lower, joint.upper, joint.velocity, q_reference_[j]}) put(d);
      put(joint.has_limits);
    }
  }
  put(standing_height_m_);
  put(crouch_knee_rad_);
  for (const LegGeometry& g : legs_) put(g.foot0_rad);
  return bytes;
}

const Vec3& BipedLegs::FootPoint_L(Side s, FootPoint which) const {
  const LegGeometry& g = leg(s);
  switch (which) {
    case FootPoint::kHeel: return g.p_L_heel;
    case FootPoint::kToe: return g.p_L_toe;
    case FootPoint::kMid: break;
  }
  return g.p_L_sole;
}

Vec3 BipedLegs::Point3(Side s, const LegAnglesRad& a, FootPoint which) const {
  return FootPose_P(s, a) * FootPoint_L(s, which);
}

std::array<double, 3> BipedLegs::JointValues(Side s, const LegAnglesRad& a) const {
  const LegGeometry& g = leg(s);
  return {g.hip_sign * (g.thigh0_rad - a.hip), g.knee_sign * (a.knee - (g.thigh0_rad - g.shank0_rad)),
          g.ankle_sign * ((a.hip - a.knee) - g.shank0_rad - (a.pitch - g.foot0_rad))};
}

void BipedLegs::WriteJoints(Side s, const LegAnglesRad& a, std::span<double> q) const {
  const LegGeometry& g = leg(s);
  const std::array<double, 3> v = JointValues(s, a);
  q[g.hip_joint] = v[0];
  q[g.knee_joint] = v[1];
  q[g.ankle_joint] = v[2];
}

LegAnglesRad BipedLegs::ReadJoints(Side s, std::span<const double> q) const {
  const LegGeometry& g = leg(s);
  LegAnglesRad a;
  a.hip = g.thigh0_rad - q[g.hip_joint] / g.hip_sign;
  a.knee = q[g.knee_joint] / g.knee_sign + (g.thigh0_rad - g.shank0_rad);
  a.pitch = (a.hip - a.knee) - g.shank0_rad - q[g.ankle_joint] / g.ankle_sign + g.foot0_rad;
  return a;
}

}  // namespace proxsim
