// Taylor series by Horner's rule, in a fixed order of + and ×: no libm
// (see portable_trig.h for why).
#include "scene/portable_trig.h"

#include <cassert>

namespace proxsim::gen {

namespace {

// Σ_{k=0..12} (−1)^k x^(2k+offset) / (2k+offset)!, offset 1 for sin, 0 for cos:
// from the last term inward, each step dividing by the next two factors.
double Series(double x, int offset) {
  constexpr int kTerms = 13;
  const double x2 = x * x;
  double sum = 1.0;
  for (int k = kTerms - 1; k >= 1; --k) {
    const double n = 2.0 * k + offset;  // the term's power
    sum = 1.0 - x2 / (n * (n - 1.0)) * sum;
  }
  return offset == 1 ? x * sum : sum;
}

constexpr double kHalfPi = 1.5707963267948966;

}  // namespace

double PortableSin(double x_rad) {
  assert(x_rad >= -kHalfPi && x_rad <= kHalfPi && "PortableSin: |x| <= pi/2 only");
  return Series(x_rad, 1);
}

double PortableCos(double x_rad) {
  assert(x_rad >= -kHalfPi && x_rad <= kHalfPi && "PortableCos: |x| <= pi/2 only");
  return Series(x_rad, 0);
}

}  // namespace proxsim::gen
