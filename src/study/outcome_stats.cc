#include "study/outcome_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace proxsim {

double NormalQuantile(double p) { return boost::math::quantile(boost::math::normal_distribution<double>(), p); }

double StudentTQuantile(double p, double dof) {
  return boost::math::quantile(boost::math::students_t_distribution<double>(dof), p);
}

PerceptionScore PerceptionScoreOf(std::span<const char> set, std::span<const char> blind, std::span<const char> oracle) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = set.size();
  double sum_x = 0, sum_y = 0;
  for (std::size_t j = 0; j < n; ++j) {
    sum_x += set[j] - blind[j];
    sum_y += oracle[j] - blind[j];
  }
  if (n < 2 || sum_y <= 0) return {sum_y > 0 ? sum_x / sum_y : kNaN, kNaN, kNaN};
  const double r = sum_x / sum_y, mean_y = sum_y / static_cast<double>(n);
  double sum_z2 = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const double z = (set[j] - blind[j]) - r * (oracle[j] - blind[j]);
    sum_z2 += z * z;
  }
  const double half = kZ95 * std::sqrt(sum_z2 / (static_cast<double>(n) * static_cast<double>(n - 1))) / mean_y;
  return {r, r - half, r + half};
}

Interval WilsonInterval95(std::int64_t successes, std::int64_t n) {
  if (n <= 0) return {0.0, 1.0};
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(successes) / nn;
  const double z2 = kZ95 * kZ95;
  const double denominator = 1.0 + z2 / nn;
  const double centre = (p + z2 / (2.0 * nn)) / denominator;
  const double half = kZ95 / denominator * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn));
  // rounding must not carry the ends past [0, 1]
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

double McNemarExactP(std::int64_t b, std::int64_t c) {
  const std::int64_t n = b + c;
  if (n <= 0) return 1.0;
  const std::int64_t k = std::min(b, c);
  double tail = 0;
  if (n <= 1000) {
    // C(n, i) / 2^n term by term from 2^-n: exact while C(n, i) has at most 53 bits
    double term = std::ldexp(1.0, -static_cast<int>(n));
    for (std::int64_t i = 0; i <= k; ++i) {
      tail += term;
      term = term * static_cast<double>(n - i) / static_cast<double>(i + 1);
    }
  } else {
    // beyond, 2^-n underflows: each term in logs
    const double log_half_n = -static_cast<double>(n) * std::log(2.0);
    for (std::int64_t i = 0; i <= k; ++i) {
      const double log_choose = std::lgamma(static_cast<double>(n) + 1) - std::lgamma(static_cast<double>(i) + 1) -
                                std::lgamma(static_cast<double>(n - i) + 1);
      tail += std::exp(log_choose + log_half_n);
    }
  }
  return std::min(1.0, 2.0 * tail);
}

double Median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

}  // namespace proxsim
