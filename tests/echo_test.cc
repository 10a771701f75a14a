// The sensors' shared physics outside the models: the wave speed a flight is
// timed with, the point a distance along a ray stands for, the echo of a hit,
// the draws of one key and a beam ray's world direction — each against values
// computed here by trigonometry or from the functions' definitions.
#include "sensors/echo.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "sensors/beam.h"
#include "sensors/measured_point.h"
#include "sensors/noise.h"
#include "sensors/wave_speed.h"

namespace proxsim {
namespace {

// a sensor's axis pitched down by pitch_deg in the x–z plane (y left, z up)
Vec3 AxisPitchedDown(double pitch_deg) {
  const double a = DegToRad(pitch_deg);
  return Vec3(std::cos(a), 0, -std::sin(a));
}

bool BitIdentical(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

TEST(WaveSpeed, ByTypeSoundForUltrasonicLightOtherwise) {
  EXPECT_EQ(WaveSpeed_m_s(SensorType::kUltrasonic, 0.0), 343.0);
  for (SensorType type : {SensorType::kIdeal, SensorType::kLaser, SensorType::kReflectance, SensorType::kLookup}) {
    EXPECT_EQ(WaveSpeed_m_s(type, 0.0), 299792458.0) << SensorTypeName(type);
  }
}

TEST(WaveSpeed, APositiveOverrideWinsForEveryType) {
  for (SensorType type : {SensorType::kIdeal, SensorType::kLaser, SensorType::kUltrasonic, SensorType::kReflectance,
                          SensorType::kLookup}) {
    EXPECT_EQ(WaveSpeed_m_s(type, 1500.0), 1500.0) << SensorTypeName(type);  // sound in water
    // 0 (the scenario's default) and anything not positive mean "by type"
    EXPECT_EQ(WaveSpeed_m_s(type, -1.0), WaveSpeed_m_s(type, 0.0)) << SensorTypeName(type);
  }
}

// a sensor 0.5 m above the floor, its axis 30° down: the floor is d = h/sin 30° = 1 m
// away along it, at x = d·cos 30° ahead of the sensor
TEST(MeasuredPoint, LiesAlongTheAxisAtTheDistance) {
  const Vec3 p_WS(1.0, 2.0, 0.5);
  const Vec3 dir_W = AxisPitchedDown(30);
  const double d_m = 0.5 / std::sin(DegToRad(30));
  const Vec3 p_W = MeasuredPoint_W(p_WS, dir_W, d_m);
  EXPECT_NEAR(p_W.x(), 1.0 + d_m * std::cos(DegToRad(30)), 1e-12);
  EXPECT_NEAR(p_W.y(), 2.0, 1e-12);
  EXPECT_NEAR(p_W.z(), 0.0, 1e-12);
  EXPECT_NEAR((p_W - p_WS).norm(), d_m, 1e-12);
  EXPECT_EQ(MeasuredPoint_W(p_WS, dir_W, 0.0), p_WS);
}

TEST(EchoOfHit, KeepsTheDistanceAndMeasuresIncidenceFromTheNormal) {
  // the floor met by an axis pitched down θ: incidence 90° − θ
  for (double pitch_deg : {10.0, 30.0, 45.0, 80.0, 90.0}) {
    const Echo echo = EchoOfHit(1.25, AxisPitchedDown(pitch_deg), Vec3::UnitZ());
    EXPECT_EQ(echo.distance_m, 1.25);
    EXPECT_NEAR(echo.incidence_deg, 90.0 - pitch_deg, 1e-9) << pitch_deg;
  }
  // a wall turned by ψ about z, met by a horizontal ray along +x: incidence ψ, from either side
  for (double yaw_deg : {0.0, 20.0, 60.0}) {
    const double psi = DegToRad(yaw_deg);
    const Vec3 normal_W(-std::cos(psi), -std::sin(psi), 0);
    EXPECT_NEAR(EchoOfHit(2.0, Vec3::UnitX(), normal_W).incidence_deg, yaw_deg, 1e-6) << yaw_deg;
    EXPECT_NEAR(EchoOfHit(2.0, Vec3::UnitX(), -normal_W).incidence_deg, yaw_deg, 1e-6) << yaw_deg;
  }
}

TEST(EchoOfHit, LeavesTheMaterialAndTheFlightAtTheirDefaults) {
  const Echo echo = EchoOfHit(0.7, Vec3::UnitX(), -Vec3::UnitX());
  const Echo defaults;
  EXPECT_EQ(echo.from_robot, defaults.from_robot);
  EXPECT_EQ(echo.ir_albedo, defaults.ir_albedo);
  EXPECT_EQ(echo.acoustic_reflectivity, defaults.acoustic_reflectivity);
  EXPECT_EQ(echo.specular, defaults.specular);
  EXPECT_EQ(echo.flight_shift_m, 0.0);
}

TEST(KeyedNoiseDraw, IsTheKeysGaussianAndADropoutUniformOfItsOwnKey) {
  const NoiseKey key{7, 3, 11, 5};
  NoiseSpec noise;
  const NoiseDraw without = KeyedNoiseDraw(noise, key);
  EXPECT_EQ(without.gaussian_g, KeyedGaussian(key));
  EXPECT_EQ(without.uniform, 1.0) << "no dropout: never dropped, and no draw made";

  noise.dropout = 0.2;
  const NoiseDraw with = KeyedNoiseDraw(noise, key);
  EXPECT_EQ(with.gaussian_g, without.gaussian_g) << "the dropout must not change G";
  NoiseKey dropout_key = key;
  dropout_key.ray = key.ray | 0x80000000u;
  EXPECT_EQ(with.uniform, KeyedUniforms(dropout_key).u1);
}

TEST(BeamRayDir, AxisIsTheSensorsXColumnAndRingsLieAtTheirAngle) {
  const Pose X_WS = PoseFromXyzRpy(Vec3(0.1, -0.2, 0.4), Vec3(DegToRad(5), DegToRad(25), DegToRad(-40)));
  const Vec3 axis_W = X_WS.linear().col(0);
  BeamSpec beam;
  beam.aperture_deg = 30;
  beam.rays = 19;
  const std::vector<BeamRay> rays = MakeBeamRays(beam);
  ASSERT_EQ(rays.size(), 19u);
  for (const BeamRay& ray : rays) {
    const Vec3 dir_W = BeamRayDir_W(X_WS, ray);
    EXPECT_NEAR(dir_W.norm(), 1.0, 1e-12);
    if (ray.off_axis_deg == 0.0) {
      EXPECT_TRUE(BitIdentical(dir_W, axis_W)) << "the axis ray is the paper's single ray, bit for bit";
    } else {
      EXPECT_NEAR(RadToDeg(std::acos(std::clamp(dir_W.dot(axis_W), -1.0, 1.0))), ray.off_axis_deg, 1e-9);
    }
  }
}

}  // namespace
}  // namespace proxsim
