// The statistics of an outcome study's answers (docs/studies.md "Outcome
// mode"), in closed form:
//
// - the 95 % Wilson score interval of a success rate k/n (Wilson 1927): with
//   p = k/n and z = 1.959963984540054,
//     centre = (p + z²/2n) / (1 + z²/n),
//     half   = z / (1 + z²/n) · √(p(1−p)/n + z²/4n²);
//   unlike p ± z√(p(1−p)/n) it stays in [0, 1] and is not of zero width at
//   0 or n successes (10/10 gives [0.722, 1]);
// - McNemar's test of two sets run on the same worlds and seeds, exact: of
//   the b + c discordant pairs (b: A succeeded where B failed, c: the other
//   way), under "A and B are as good" each is A's with probability 1/2, so
//     p = min(1, 2 · Σ_{i=0}^{min(b,c)} C(b+c, i) / 2^(b+c))
//   (two-sided, exact binomial; 1 when there is no discordant pair). Exact
//   rather than the chi-square approximation, which is poor below about 25
//   discordant pairs — the usual case in a small study.
// - the perception score of a set: where its success lies between the blind
//   baseline's and the oracle's on the same worlds, R = (S − B) / (O − B),
//   with a 95 % interval by the delta method on the paired worlds: with
//   x_j = S_j − B_j and y_j = O_j − B_j (each −1, 0 or 1) on world j of n,
//   R = Σx / Σy, and with z_j = x_j − R·y_j (whose mean is 0),
//     Var R ≈ Σ z_j² / (n (n − 1)) / ȳ²,   R ± z₀.₉₇₅ √Var R;
//   undefined (NaN) when the oracle does no better than blind (Σy <= 0).
//
// Every quantile comes from Boost.Math (boost/math/distributions), checked
// against published tables in tests/outcome_study_test.cc.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace proxsim {

/// The standard normal's quantile at probability p in (0, 1) (Boost.Math).
double NormalQuantile(double p);
/// Student's t's quantile at probability p in (0, 1) for `dof` >= 1 degrees of freedom (Boost.Math).
double StudentTQuantile(double p, double dof);

/// z of a two-sided 95 % interval (the normal's 97.5 % quantile; NormalQuantile(0.975) to the last bit, tested).
inline constexpr double kZ95 = 1.959963984540054;

struct Interval {
  double low = 0, high = 0;
};

/// The 95 % Wilson score interval of `successes` out of `n` (n > 0); [0, 1] for n = 0.
Interval WilsonInterval95(std::int64_t successes, std::int64_t n);

/// McNemar's exact two-sided p-value from the discordant counts b and c.
double McNemarExactP(std::int64_t b, std::int64_t c);

/// A perception score and its 95 % interval (all NaN when undefined).
struct PerceptionScore {
  double score, low, high;
};
/// From the paired successes (0 or 1) of the set, blind and the oracle on the same n worlds.
PerceptionScore PerceptionScoreOf(std::span<const char> set, std::span<const char> blind, std::span<const char> oracle);

/// The median of `values` (the mean of the middle two for an even count); NaN for none.
double Median(std::vector<double> values);

}  // namespace proxsim
