// Legs that step on what the robot knows (`gait.footholds: map`,
// docs/terrain.md): how a landed sole is felt on the true ground
// (gait/touchdown.h) against hand-made grounds; the walker planning on one
// ground while another is the truth (settling within the tolerance with its
// pelvis continuous, falling beyond it); and the map-backed terrain
// (sim/map_terrain.h) answering from the map an ideal run built.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gait/gait_walker.h"
#include "gait/touchdown.h"
#include "robot/robot_model.h"
#include "scenario/scenario.h"
#include "sim/map_terrain.h"
#include "sim/simulation.h"

namespace proxsim {
namespace {

// A ground given as its height at (x, y): kNoGround where there is none.
class HeightField : public TerrainQuery {
 public:
  explicit HeightField(std::function<double(double, double)> z_at) : z_at_(std::move(z_at)) {}
  void HeightsBelow(std::span<const Vec3> from_W, double depth_m, std::span<double> z_W) const override {
    for (std::size_t i = 0; i < from_W.size(); ++i) {
      const double z = z_at_(from_W[i].x(), from_W[i].y());
      z_W[i] = std::isnan(z) ? kUnknownGround
               : z > from_W[i].z() ? kBlockedGround
               : z < from_W[i].z() - depth_m ? kNoGround
                                              : z;
    }
  }

 private:
  std::function<double(double, double)> z_at_;
};

// A sole 0.26 m long, 0.10 m wide, heel at x = 1.0, along +x at y = 0.
LandedSole SoleFrom(double heel_x_m, double z_m) {
  LandedSole sole;
  sole.p_W = {Vec3(heel_x_m, 0, z_m), Vec3(heel_x_m + 0.07, 0, z_m), Vec3(heel_x_m + 0.26, 0, z_m)};
  sole.across_W = Vec3::UnitY();
  sole.half_width_m = 0.05;
  return sole;
}

constexpr double kReach_m = 0.98;
constexpr double kTolerance_m = 0.02;

TEST(FootholdsMapTouchdown, ASoleOnTheGroundItWasPlannedOnRestsThere) {
  const HeightField floor([](double, double) { return 0.30; });
  const Touchdown t = FeelTouchdown(floor, SoleFrom(1.0, 0.30), 0.30, kTolerance_m, kReach_m);
  EXPECT_FALSE(t.fell) << t.reason;
  EXPECT_EQ(t.rest_z_m, 0.30);
}

TEST(FootholdsMapTouchdown, WithinTheToleranceItSettlesOnTheTrueGroundLowerOrHigher) {
  for (const double true_z : {0.30 - 0.019, 0.30 + 0.01}) {
    const HeightField floor([&](double, double) { return true_z; });
    const Touchdown t = FeelTouchdown(floor, SoleFrom(1.0, 0.30), 0.30, kTolerance_m, kReach_m);
    EXPECT_FALSE(t.fell) << t.reason;
    EXPECT_EQ(t.rest_z_m, true_z);
  }
}

TEST(FootholdsMapTouchdown, LowerThanPlannedBeyondTheToleranceFallsNamingWhere) {
  const HeightField floor([](double, double) { return 0.15; });
  const Touchdown t = FeelTouchdown(floor, SoleFrom(1.0, 0.30), 0.30, kTolerance_m, kReach_m);
  ASSERT_TRUE(t.fell);
  EXPECT_NE(t.reason.find("0.150 m lower than planned at (1.00, 0.00)"), std::string::npos) << t.reason;
}

TEST(FootholdsMapTouchdown, NothingUnderTheSoleFalls) {
  const HeightField nothing([](double, double) { return -1e9; });
  const Touchdown t = FeelTouchdown(nothing, SoleFrom(2.5, 0.0), 0.0, kTolerance_m, kReach_m);
  ASSERT_TRUE(t.fell);
  EXPECT_NE(t.reason.find("landed on nothing at (2.50, 0.00)"), std::string::npos) << t.reason;
}

TEST(FootholdsMapTouchdown, TheHighestGroundUnderTheSoleHoldsItUnlessOnlyItsToeIsOnIt) {
  // a step down of 0.15 m at x = 1.2: heel and middle (x 1.0, 1.07) on the
  // upper tread, the toe (1.26) over the lower one: it rests on the upper one
  const HeightField step_down([](double x, double) { return x < 1.2 ? 0.30 : 0.15; });
  const Touchdown on_heel = FeelTouchdown(step_down, SoleFrom(1.0, 0.30), 0.30, kTolerance_m, kReach_m);
  EXPECT_FALSE(on_heel.fell) << on_heel.reason;
  EXPECT_EQ(on_heel.rest_z_m, 0.30);
  // a step up at x = 1.2: only the toe is on the upper tread: it tips off
  const HeightField step_up([](double x, double) { return x < 1.2 ? 0.15 : 0.30; });
  const Touchdown on_toe = FeelTouchdown(step_up, SoleFrom(1.0, 0.30), 0.30, kTolerance_m, kReach_m);
  ASSERT_TRUE(on_toe.fell);
  EXPECT_NE(on_toe.reason.find("on its toe alone"), std::string::npos) << on_toe.reason;
  // a hole under the heel and the middle, the toe beyond it on the floor
  const HeightField hole([](double x, double) { return x < 1.2 ? -1e9 : 0.0; });
  const Touchdown over_hole = FeelTouchdown(hole, SoleFrom(1.0, 0.0), 0.0, kTolerance_m, kReach_m);
  ASSERT_TRUE(over_hole.fell);
  EXPECT_NE(over_hole.reason.find("the ground under its heel is missing"), std::string::npos) << over_hole.reason;
  // the sole's edge over a ledge beside it still rests on the ledge (across: the highest line)
  const HeightField ledge([](double, double y) { return y > 0.04 ? 0.30 : 0.0; });
  const Touchdown on_edge = FeelTouchdown(ledge, SoleFrom(1.0, 0.30), 0.30, kTolerance_m, kReach_m);
  EXPECT_FALSE(on_edge.fell) << on_edge.reason;
  EXPECT_EQ(on_edge.rest_z_m, 0.30);
}

// The walker planning on `footholds` while `truth` is the ground, 200 Hz.
struct Walked {
  std::vector<LocomotionEvent> events;
  std::vector<double> stance_heel_z;  // each new stance heel's height, in order
  double max_pelvis_dz_m = 0;         // between samples
  double pelvis_x_m = 0;
};

Walked WalkOn(const TerrainQuery& truth, const TerrainQuery* footholds, double seconds, double tolerance_m = 0.02) {
  WalkConfig config;
  config.gait.stride_m = 0.6;
  config.gait.period_s = 1.2;
  config.gait.touchdown_tolerance_m = tolerance_m;
  config.waypoints_m = {Vec2(0, 0), Vec2(20, 0)};
  GaitWalker walker(RobotModel::Builtin("biped"), config);
  walker.SetTerrain(&truth, footholds);
  Walked w;
  double last_z = NAN;
  Vec3 last_heel = Vec3::Constant(NAN);
  for (int i = 0; i <= seconds * 200; ++i) {
    const RobotState s = walker.Advance(i / 200.0);
    for (LocomotionEvent& e : walker.TakeEvents()) w.events.push_back(e);
    const Vec3& heel = walker.current_step().p_W_heel;
    if (heel != last_heel) w.stance_heel_z.push_back(heel.z());
    last_heel = heel;
    const double z = s.X_WP.translation().z();
    if (!std::isnan(last_z)) w.max_pelvis_dz_m = std::max(w.max_pelvis_dz_m, std::abs(z - last_z));
    last_z = z;
    w.pelvis_x_m = s.X_WP.translation().x();
  }
  return w;
}

TEST(FootholdsMapWalker, AMapThatKnowsNothingWalksLevelAtTheStanceHeightAsOnAFlatFloor) {
  const HeightField floor([](double, double) { return 0.0; });
  const HeightField unknown([](double, double) { return kUnknownGround; });
  const Walked truth = WalkOn(floor, nullptr, 4.0);
  const Walked blind = WalkOn(floor, &unknown, 4.0);
  EXPECT_TRUE(blind.events.empty());
  EXPECT_EQ(blind.stance_heel_z, truth.stance_heel_z);
  EXPECT_EQ(blind.pelvis_x_m, truth.pelvis_x_m);
}

// The true floor, and a map that holds it except for a phantom tread `dz_m`
// high where the right foot lands first (x 0.3 .. 0.7, y < 0).
double PhantomTread(double x, double y, double dz_m) { return x > 0.3 && x < 0.7 && y < 0 ? dz_m : 0.0; }

TEST(FootholdsMapWalker, AFootPlannedOnAPhantomTreadSettlesWithinTheToleranceAndFallsBeyondIt) {
  const HeightField floor([](double, double) { return 0.0; });
  const HeightField within([](double x, double y) { return PhantomTread(x, y, 0.015); });
  const Walked settled = WalkOn(floor, &within, 1.3);
  for (const LocomotionEvent& e : settled.events) EXPECT_NE(e.event, "fall") << e.detail;
  ASSERT_GE(settled.stance_heel_z.size(), 2u);
  EXPECT_EQ(settled.stance_heel_z[1], 0.0);  // the right foot stands on the true floor, not the phantom
  EXPECT_LT(settled.max_pelvis_dz_m, 0.002);  // and the pelvis moves on continuously: within 2 mm per 5 ms
  // a phantom dip: the true floor is met 15 mm higher than planned, and the foot settles on it
  const HeightField dip([](double x, double y) { return PhantomTread(x, y, -0.015); });
  const Walked met = WalkOn(floor, &dip, 1.3);
  for (const LocomotionEvent& e : met.events) EXPECT_NE(e.event, "fall") << e.detail;
  ASSERT_GE(met.stance_heel_z.size(), 2u);
  EXPECT_EQ(met.stance_heel_z[1], 0.0);
  EXPECT_LT(met.max_pelvis_dz_m, 0.002);

  const HeightField beyond([](double x, double y) { return PhantomTread(x, y, 0.03); });
  const Walked fell = WalkOn(floor, &beyond, 6.0);
  ASSERT_EQ(fell.events.size(), 1u);
  EXPECT_EQ(fell.events[0].event, "fall");
  EXPECT_NE(fell.events[0].detail.find("the right foot landed 0.030 m lower than planned"), std::string::npos)
      << fell.events[0].detail;
  EXPECT_EQ(fell.stance_heel_z.size(), 1u);  // it stands where it fell
  // a tolerance of 4 cm lets the same landing settle
  const Walked tolerant = WalkOn(floor, &beyond, 1.3, 0.04);
  for (const LocomotionEvent& e : tolerant.events) EXPECT_NE(e.event, "fall") << e.detail;
  ASSERT_GE(tolerant.stance_heel_z.size(), 2u);
  EXPECT_EQ(tolerant.stance_heel_z[1], 0.0);
}

TEST(FootholdsMapTerrain, AnswersTheHeightsTheMapHoldsAndUnknownElsewhere) {
  // the ideal example's map at the end of its run: the treads it saw exactly
  Simulation sim(LoadScenarioFile(std::string(PROXSIM_SOURCE_DIR) + "/data/scenarios/stairs_footholds_map.yaml"));
  while (!sim.done()) sim.Step();
  const MapTerrain terrain(*sim.terrain_map());
  const std::vector<Vec3> from_W = {Vec3(1.15, 0.1, 1.5),   // the first tread, 0.15 m
                                    Vec3(2.5, -0.1, 1.5),   // the landing, 0.60 m
                                    Vec3(1.15, 0.1, 0.1),   // below the first tread: inside it
                                    Vec3(1.15, 0.1, 1.5),   // too shallow to reach it (depth 0.5 below)
                                    Vec3(8.0, 1.0, 1.5)};   // never seen
  std::vector<double> z(from_W.size());
  terrain.HeightsBelow(std::span(from_W).first(3), 3.0, std::span(z).first(3));
  terrain.HeightsBelow(std::span(from_W).subspan(3, 1), 0.5, std::span(z).subspan(3, 1));
  terrain.HeightsBelow(std::span(from_W).subspan(4, 1), 3.0, std::span(z).subspan(4, 1));
  EXPECT_NEAR(z[0], 0.15, 1e-6);
  EXPECT_NEAR(z[1], 0.60, 1e-6);
  EXPECT_EQ(z[2], kBlockedGround);
  EXPECT_EQ(z[3], kNoGround);
  EXPECT_TRUE(std::isnan(z[4]));
  // the cell answered is the map's own
  const TerrainCell* cell = sim.terrain_map()->CellAt(1.15, 0.1);
  ASSERT_NE(cell, nullptr);
  EXPECT_EQ(z[0], static_cast<double>(cell->elevation_m));
}

}  // namespace
}  // namespace proxsim
