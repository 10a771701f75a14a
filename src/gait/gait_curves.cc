#include "gait/gait_curves.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry.h"

namespace proxsim {

namespace {

double Wrap01(double p) {
  // (a phase already in [0, 1) is its own remainder: fmod would return it
  // unchanged, bit for bit, at ~20 instructions a call)
  if (p >= 0.0 && p < 1.0) return p;
  p = std::fmod(p, 1.0);
  return p < 0 ? p + 1.0 : p;
}

double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

// The curves' own toe-up foot pitch, degrees: (hip − tilt) − knee + ankle,
// from the three curves' values at one phase.
double RawPitchDeg(double hip_deg, double knee_deg, double ankle_deg) {
  return hip_deg - kPelvicTiltDeg - knee_deg + ankle_deg;
}
double RawPitchDeg(double p) {
  return RawPitchDeg(NormativeHipFlexionDeg()(p), NormativeKneeFlexionDeg()(p), NormativeAnkleDorsiflexionDeg()(p));
}

// Zero crossing of RawPitchDeg between a and b (sign change assumed), by bisection.
double PitchZero(double a, double b) {
  const double fa = RawPitchDeg(a);
  for (int i = 0; i < 80; ++i) {
    const double m = 0.5 * (a + b);
    if ((RawPitchDeg(m) > 0) == (fa > 0)) a = m; else b = m;
  }
  return 0.5 * (a + b);
}

struct FlatWindow {
  double foot_flat, heel_off;
};

const FlatWindow& Window() {
  static const FlatWindow w = [] {
    // foot-flat: first sign change after heel strike; heel-off: last one before 0.5.
    constexpr int n = 1000;
    double ff = -1, ho = -1;
    for (int i = 0; i < n / 2; ++i) {
      const double a = 0.5 * i / (n / 2), b = 0.5 * (i + 1) / (n / 2);
      if ((RawPitchDeg(a) > 0) != (RawPitchDeg(b) > 0)) {
        if (ff < 0) ff = PitchZero(a, b);
        ho = PitchZero(a, b);
      }
    }
    if (ff <= 0 || ho <= ff || RawPitchDeg(0.0) <= 0 || RawPitchDeg(0.5) >= 0)
      throw std::logic_error("gait curves: no heel rocker / toe rocker in stance");
    return FlatWindow{ff, ho};
  }();
  return w;
}

constexpr double kRampPhase = 0.03;  // width of the C1 ramps into and out of foot-flat

}  // namespace

PeriodicCurve::PeriodicCurve(std::vector<std::pair<double, double>> key_points) {
  const int n = static_cast<int>(key_points.size());
  for (const auto& [p, v] : key_points) {
    phase_.push_back(p);
    value_.push_back(v);
  }
  // Catmull-Rom tangents on the periodic, non-uniform knots.
  slope_.resize(n);
  for (int i = 0; i < n; ++i) {
    const int prev = (i + n - 1) % n, next = (i + 1) % n;
    const double t_prev = phase_[prev] - (prev > i ? 1.0 : 0.0);
    const double t_next = phase_[next] + (next < i ? 1.0 : 0.0);
    slope_[i] = (value_[next] - value_[prev]) / (t_next - t_prev);
  }
}

double PeriodicCurve::operator()(double phase) const {
  const double p = Wrap01(phase);
  const int n = static_cast<int>(phase_.size());
  int i = static_cast<int>(std::upper_bound(phase_.begin(), phase_.end(), p) - phase_.begin()) - 1;
  if (i < 0) i = n - 1;  // before the first knot: the segment that wraps
  const int j = (i + 1) % n;
  double t0 = phase_[i], t1 = phase_[j];
  double x = p;
  if (t1 <= t0) t1 += 1.0;
  if (x < t0) x += 1.0;
  const double h = t1 - t0, s = (x - t0) / h;
  const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  return h00 * value_[i] + h10 * h * slope_[i] + h01 * value_[j] + h11 * h * slope_[j];
}

const PeriodicCurve& NormativeHipFlexionDeg() {
  static const PeriodicCurve c({{0.00, 30}, {0.10, 25}, {0.30, 10}, {0.50, -10}, {0.62, -5},
                                {0.75, 25}, {0.85, 32}});
  return c;
}

const PeriodicCurve& NormativeKneeFlexionDeg() {
  static const PeriodicCurve c({{0.00, 5}, {0.12, 18}, {0.25, 5}, {0.40, 3}, {0.55, 35},
                                {0.70, 62}, {0.85, 25}, {0.95, 8}});
  return c;
}

const PeriodicCurve& NormativeAnkleDorsiflexionDeg() {
  static const PeriodicCurve c({{0.00, 0}, {0.08, -5}, {0.25, 5}, {0.40, 10}, {0.55, 5},
                                {0.62, -15}, {0.70, -5}, {0.85, 0}});
  return c;
}

double FootFlatPhase() { return Window().foot_flat; }
double HeelOffPhase() { return Window().heel_off; }

LegAnglesRad CurveLegAngles(double phase, double amplitude, double push_off_gain) {
  const double p = Wrap01(phase);
  // each curve evaluated once (the pitch reads the hip and knee again)
  const double hip_deg = NormativeHipFlexionDeg()(p), knee_deg = NormativeKneeFlexionDeg()(p);
  LegAnglesRad a;
  a.hip = amplitude * DegToRad(hip_deg - kPelvicTiltDeg);
  a.knee = amplitude * DegToRad(knee_deg);
  double pitch = amplitude * DegToRad(RawPitchDeg(hip_deg, knee_deg, NormativeAnkleDorsiflexionDeg()(p)));
  if (p <= 0.5) {
    // Flatten the stance foot between foot-flat and heel-off (C1 ramps outside).
    const FlatWindow& w = Window();
    double flat = 0;
    if (p < w.foot_flat) flat = Smoothstep((p - (w.foot_flat - kRampPhase)) / kRampPhase);
    else if (p <= w.heel_off) flat = 1;
    else flat = 1 - Smoothstep((p - w.heel_off) / kRampPhase);
    pitch *= 1 - flat;
    if (p > w.heel_off) pitch *= push_off_gain;
  }
  a.pitch = pitch;
  return a;
}

}  // namespace proxsim
