#include "gait/leg_map_suggestion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "gait/leg_kinematics.h"

namespace proxsim {

namespace {

// A chain's lowest link is a foot when it reaches this close to the robot's
// lowest point: both feet stand on the floor at the reference pose, the
// hands hang far higher.
constexpr double kFootReach_m = 0.05;
// Along a chain, the foot is the first link reaching this close to the
// chain's lowest point (a foot rather than a toe link below it): the
// tolerance with which the gait finds the sole (gait/leg_kinematics.h).
constexpr double kSoleTolerance_m = 0.002;

// Links from the root to `link`, root first.
std::vector<int> LinksFromRoot(const RobotModel& model, int link) {
  std::vector<int> chain;
  for (int l = link; l >= 0;) {
    chain.push_back(l);
    const int joint = model.link(l).parent_joint;
    l = joint >= 0 ? model.joint(joint).parent_link : -1;
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

std::vector<FootCandidate> FindFeet(const RobotModel& model, const RobotSummary& summary) {
  std::vector<std::optional<BoundingBox>> box_W(model.link_count());
  double lowest_z_m = std::numeric_limits<double>::infinity();
  for (const LinkSummary& link : summary.links) {
    box_W[link.link] = link.box_W;
    if (link.box_W) lowest_z_m = std::min(lowest_z_m, link.box_W->min_m.z());
  }
  std::vector<FootCandidate> feet;
  for (int leaf = 0; leaf < model.link_count(); ++leaf) {
    if (!model.link(leaf).child_joints.empty()) continue;
    const std::vector<int> chain = LinksFromRoot(model, leaf);
    double chain_low_m = std::numeric_limits<double>::infinity();
    for (const int l : chain)
      if (box_W[l]) chain_low_m = std::min(chain_low_m, box_W[l]->min_m.z());
    if (!(chain_low_m <= lowest_z_m + kFootReach_m)) continue;
    // the first link of the chain that reaches its bottom
    for (const int l : chain) {
      if (!box_W[l] || box_W[l]->min_m.z() > chain_low_m + kSoleTolerance_m) continue;
      if (std::ranges::none_of(feet, [&](const FootCandidate& f) { return f.link == l; })) {
        feet.push_back({l, box_W[l]->min_m.z(), 0.5 * (box_W[l]->min_m.y() + box_W[l]->max_m.y())});
      }
      break;
    }
  }
  std::ranges::sort(feet, [](const FootCandidate& a, const FootCandidate& b) { return a.y_m > b.y_m; });
  return feet;
}

// The first link with geometry among those fixed to `link` (directly or
// through other fixed joints), breadth first; −1 when there is none.
int FirstFixedWithShapes(const RobotModel& model, int link) {
  std::vector<int> todo = {link};
  for (std::size_t i = 0; i < todo.size(); ++i) {
    for (const int j : model.link(todo[i]).child_joints) {
      if (model.joint(j).type != JointType::kFixed) continue;
      const int child = model.joint(j).child_link;
      if (!model.link(child).shapes.empty()) return child;
      todo.push_back(child);
    }
  }
  return -1;
}

// Hip, knee and ankle pitch on the chain to `foot`, by axis and height.
LegSuggestion SuggestLeg(const RobotModel& model, const RobotSummary& summary, const FootCandidate& foot) {
  LegSuggestion leg;
  const double cos_tilt = std::cos(DegToRad(kMaxPitchAxisTilt_deg));
  std::vector<int> pitch;  // root first
  for (const int l : LinksFromRoot(model, foot.link)) {
    const int j = model.link(l).parent_joint;
    if (j < 0 || model.joint(j).type != JointType::kRevolute) continue;
    const Vec3 axis_W = summary.X_WJ[j].linear() * model.joint(j).axis_J;
    if (std::abs(axis_W.y()) >= cos_tilt) pitch.push_back(j);
  }
  const std::string foot_name = model.link_name(foot.link);
  if (pitch.size() < 3) {
    leg.problem = "the chain from the root to '" + foot_name + "' has " + std::to_string(pitch.size()) +
                  " revolute joint(s) whose axis lies along y (within " +
                  std::to_string(static_cast<int>(kMaxPitchAxisTilt_deg)) + "°); a leg needs hip, knee and ankle pitch";
    return leg;
  }
  const auto z = [&](int j) { return summary.X_WJ[j].translation().z(); };
  const int hip = pitch.front(), ankle = pitch.back();
  // the knee: of the pitch joints between, the one nearest halfway down
  int knee = pitch[1];
  for (std::size_t i = 1; i + 1 < pitch.size(); ++i)
    if (std::abs(z(pitch[i]) - 0.5 * (z(hip) + z(ankle))) < std::abs(z(knee) - 0.5 * (z(hip) + z(ankle)))) knee = pitch[i];
  if (!(z(hip) > z(knee) && z(knee) > z(ankle))) {
    leg.problem = "the pitch joints to '" + foot_name + "' are not hip above knee above ankle: '" +
                  model.joint_name(hip) + "', '" + model.joint_name(knee) + "', '" + model.joint_name(ankle) + "'";
    return leg;
  }
  leg.names = LegNames{model.joint_name(hip), model.joint_name(knee), model.joint_name(ankle), foot_name};

  // the shank: the knee's child link, or when it has no geometry the first
  // link with some that moves with it (a URDF may hang the shin's shapes on a
  // link fixed to it)
  leg.shank_link = model.joint(knee).child_link;
  if (model.link(leg.shank_link).shapes.empty()) {
    if (const int shapes = FirstFixedWithShapes(model, leg.shank_link); shapes >= 0) leg.shank_link = shapes;
  }
  // its front, between the knee and the ankle
  const RobotLink& shank = model.link(leg.shank_link);
  const Pose X_LW = summary.X_WL[leg.shank_link].inverse();
  const Vec3 p_L_knee = X_LW * summary.X_WJ[knee].translation();
  const Vec3 p_L_ankle = X_LW * summary.X_WJ[ankle].translation();
  const Vec3 forward_L = X_LW.linear() * Vec3::UnitX();
  for (const double fraction : kShankFractions) {
    const Vec3 p_L = p_L_knee + fraction * (p_L_ankle - p_L_knee);
    const auto t_m = FarthestAlongLink_m(shank, p_L, forward_L);
    if (!t_m) continue;
    // pitch about the sensor's own y: +x turns down (REP-103, as rpy_deg [0, d, 0] does on a level link)
    const Rotation R_LS_down = X_LW.linear() * RotationFromRpy(Vec3(0, kShankPitchDown_deg * kPi / 180.0, 0));
    leg.shank_front.push_back({fraction, p_L + (*t_m + kShankStandOff_m) * forward_L,
                               RpyFromRotation(X_LW.linear()) * (180.0 / kPi),
                               RpyFromRotation(R_LS_down) * (180.0 / kPi)});
  }
  return leg;
}

}  // namespace

LegMapSuggestion SuggestLegMap(const RobotModel& model, const RobotSummary& summary) {
  LegMapSuggestion suggestion;
  suggestion.feet = FindFeet(model, summary);
  // one foot per side: the lowest of those on that side
  std::array<const FootCandidate*, 2> foot = {nullptr, nullptr};
  for (const FootCandidate& f : suggestion.feet) {
    const FootCandidate*& side = foot[f.y_m > 0 ? 0 : 1];
    if (side == nullptr || f.lowest_z_m < side->lowest_z_m) side = &f;
  }
  for (int s = 0; s < 2; ++s) {
    if (foot[s] == nullptr) {
      suggestion.legs[s].problem = std::string("no foot on the ") + (s == 0 ? "left (y > 0)" : "right (y < 0)") +
                                   ": no chain from the root reaches the ground there";
      continue;
    }
    suggestion.legs[s] = SuggestLeg(model, summary, *foot[s]);
  }
  if (!suggestion.legs[0].names || !suggestion.legs[1].names) return suggestion;
  // read by the gait's own leg reader: accepted here means accepted by validate
  try {
    const std::vector<double> q_reference(model.joint_count(), 0.0);
    const BipedLegs legs(model, std::array<LegNames, 2>{*suggestion.legs[0].names, *suggestion.legs[1].names},
                         q_reference);
    suggestion.accepted = true;
    for (int s = 0; s < 2; ++s) suggestion.ankle_zero_deg[s] = RadToDeg(legs.leg(static_cast<Side>(s)).foot0_rad);
  } catch (const InputError& error) {
    suggestion.problems = error.problems();
  }
  return suggestion;
}

}  // namespace proxsim
