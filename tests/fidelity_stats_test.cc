// The statistics of `proxsim fidelity` (src/fidelity/fidelity_stats.h) on
// cases small enough to compute by hand, and the recording reader's own
// checks (its messages through the binary: fidelity_cli_test.cc).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/input_error.h"
#include "fidelity/fidelity_stats.h"
#include "fidelity/recording_csv.h"

namespace proxsim {
namespace {

// A compared reading: recorded (d, valid) and simulated (d, valid).
ComparedReading FidelityPair(double recorded_d_m, bool recorded_valid, double simulated_d_m, bool simulated_valid) {
  return {.zone = 0,
          .ring = 0,
          .band = recorded_valid ? 0 : -1,
          .recorded_d_m = recorded_valid ? recorded_d_m : NAN,
          .recorded_valid = recorded_valid,
          .simulated_d_m = simulated_d_m,
          .simulated_valid = simulated_valid};
}

TEST(FidelityStats, QuantilesAreLinearBetweenOrderStatistics) {
  const std::vector<double> sorted = {1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(SortedQuantile(sorted, 0.5), 2.5);  // the mean of the middle two
  // p90 of 4 values: rank 0.9 · 3 = 2.7, 3 + 0.7 · (4 − 3)
  EXPECT_DOUBLE_EQ(SortedQuantile(sorted, 0.9), 3.7);
  EXPECT_DOUBLE_EQ(SortedQuantile(std::vector<double>{5}, 0.9), 5);
  EXPECT_TRUE(std::isnan(SortedQuantile(std::vector<double>{}, 0.5)));
}

TEST(FidelityStats, AHandComputedCase) {
  // errors (simulated − recorded) of the four readings both call valid:
  // +0.02, −0.01, +0.04, 0.00 on recorded 1, 1, 2, 0.5 m
  const std::vector<ComparedReading> readings = {
      FidelityPair(1.0, true, 1.02, true), FidelityPair(1.0, true, 0.99, true),  FidelityPair(2.0, true, 2.04, true),
      FidelityPair(0.5, true, 0.5, true),  FidelityPair(1.5, true, 4.0, false),  // the recording only
      FidelityPair(0, false, 1.2, true),                                  // the model only
      FidelityPair(0, false, 4.0, false), FidelityPair(0, false, 4.0, false)};   // neither
  const FidelityStats s = StatsOf(readings);
  EXPECT_EQ(s.count, 8u);
  EXPECT_EQ(s.both_valid, 4u);
  EXPECT_EQ(s.recorded_only, 1u);
  EXPECT_EQ(s.simulated_only, 1u);
  EXPECT_EQ(s.both_invalid, 2u);
  EXPECT_DOUBLE_EQ(s.validity_agreement, 6.0 / 8.0);
  // sorted errors −0.01, 0, 0.02, 0.04: median (0 + 0.02) / 2
  EXPECT_NEAR(s.median_error_m, 0.01, 1e-12);
  // |errors| sorted 0, 0.01, 0.02, 0.04: rank 2.7 → 0.02 + 0.7 · 0.02
  EXPECT_NEAR(s.p90_abs_error_m, 0.034, 1e-12);
  EXPECT_NEAR(s.bias_m, 0.05 / 4, 1e-12);
  // relative: +0.02, −0.01, +0.02, 0 → sorted −0.01, 0, 0.02, 0.02: median 0.01;
  // |.| sorted 0, 0.01, 0.02, 0.02: p90 0.02
  EXPECT_NEAR(s.median_rel_error, 0.01, 1e-12);
  EXPECT_NEAR(s.p90_abs_rel_error, 0.02, 1e-12);
}

TEST(FidelityStats, NoReadingBothCallValidLeavesTheErrorsUndefined) {
  const std::vector<ComparedReading> readings = {FidelityPair(1.0, true, 4.0, false), FidelityPair(0, false, 4.0, false)};
  const FidelityStats s = StatsOf(readings);
  EXPECT_DOUBLE_EQ(s.validity_agreement, 0.5);
  EXPECT_TRUE(std::isnan(s.median_error_m));
  EXPECT_TRUE(std::isnan(s.p90_abs_error_m));
  EXPECT_TRUE(std::isnan(s.bias_m));
}

TEST(FidelityStats, RingsCountOutwardsFromTheCentreZones) {
  // 8x8: the middle 2x2 is ring 0, the border ring 3
  for (const int zone : {27, 28, 35, 36}) EXPECT_EQ(ZoneRing(8, 8, zone), 0) << zone;
  for (const int zone : {0, 7, 56, 63, 3, 24, 39, 60}) EXPECT_EQ(ZoneRing(8, 8, zone), 3) << zone;
  EXPECT_EQ(ZoneRing(8, 8, 18), 1);  // row 2, column 2
  EXPECT_EQ(ZoneRing(8, 8, 9), 2);   // row 1, column 1
  // 4x4: the middle 2x2 and its border; 3x3: the middle zone and its border
  EXPECT_EQ(ZoneRing(4, 4, 5), 0);
  EXPECT_EQ(ZoneRing(4, 4, 0), 1);
  EXPECT_EQ(ZoneRing(3, 3, 4), 0);
  EXPECT_EQ(ZoneRing(3, 3, 1), 1);
  EXPECT_EQ(ZoneRing(1, 1, 0), 0);
}

TEST(FidelityStats, BandsAreHalfOpenFromEachEdge) {
  const std::vector<double> edges_m = {0.5, 1.0, 2.0};
  EXPECT_EQ(RangeBand(edges_m, 0.2), 0);
  EXPECT_EQ(RangeBand(edges_m, 0.5), 1);  // an edge starts its band
  EXPECT_EQ(RangeBand(edges_m, 1.999), 2);
  EXPECT_EQ(RangeBand(edges_m, 7.0), 3);
  EXPECT_EQ(RangeBandName(edges_m, 0), "0-0.5 m");
  EXPECT_EQ(RangeBandName(edges_m, 2), "1-2 m");
  EXPECT_EQ(RangeBandName(edges_m, 3), ">= 2 m");
  EXPECT_EQ(RangeBandName(edges_m, -1), "invalid");
}

TEST(FidelityStats, TablesGroupByZoneRingBandAndRingBand) {
  std::vector<ComparedReading> readings = {FidelityPair(1.0, true, 1.01, true), FidelityPair(1.0, true, 1.03, true)};
  readings[1].zone = 9;
  readings[1].ring = 2;
  readings[1].band = 1;
  const std::vector<FidelityRow> rows = FidelityTables(readings);
  // all, zones 0 and 9, rings 0 and 2, bands 0 and 1, (ring, band) (0, 0) and (2, 1)
  ASSERT_EQ(rows.size(), 9u);
  EXPECT_EQ(rows[0].table, "all");
  EXPECT_EQ(rows[0].stats.count, 2u);
  EXPECT_EQ(rows[2].table, "zone");
  EXPECT_EQ(rows[2].zone, 9);
  EXPECT_NEAR(rows[2].stats.median_error_m, 0.03, 1e-12);
  EXPECT_EQ(rows[8].table, "ring_band");
  EXPECT_EQ(rows[8].ring, 2);
  EXPECT_EQ(rows[8].band, 1);
}

TEST(FidelityRecording, ALongRecordingIsReadSampleBySample) {
  const std::string text =
      "# a comment\n"
      "t_s,x_m,y_m,z_m,qw,qx,qy,qz,zone,d_m,valid\n"
      "0,1,0,0.5,1,0,0,0,0,1.20,1\n"
      "0,1,0,0.5,1,0,0,0,1,,0\n"
      "0.1,1,0,0.5,0.7071067811865476,0,0,0.7071067811865476,1,0.9,1\n"
      "0.1,1,0,0.5,0.7071067811865476,0,0,0.7071067811865476,0,0.8,true\n";
  const Recording recording = ParseRecording(text, "r.csv", 2);
  ASSERT_EQ(recording.sample_count(), 2u);
  EXPECT_EQ(recording.first_line[1], 5);
  EXPECT_DOUBLE_EQ(recording.d_m[0], 1.20);
  EXPECT_FALSE(recording.valid[1]);
  EXPECT_DOUBLE_EQ(recording.d_m[2], 0.8);  // zone 0 of the second sample, though listed second
  EXPECT_DOUBLE_EQ(recording.d_m[3], 0.9);
  // a quarter turn about +z: the frame's +x along the world's +y
  EXPECT_NEAR((recording.X_WM[1].linear().col(0) - Vec3::UnitY()).norm(), 0.0, 1e-12);
}

TEST(FidelityRecording, ASingleZonePartMayLeaveTheZoneColumnOut) {
  const Recording recording = ParseRecording("t_s,x_m,y_m,z_m,qw,qx,qy,qz,d_m,valid\n0,0,0,0,1,0,0,0,0.5,1\n", "r.csv", 1);
  ASSERT_EQ(recording.sample_count(), 1u);
  EXPECT_DOUBLE_EQ(recording.d_m[0], 0.5);
}

}  // namespace
}  // namespace proxsim
