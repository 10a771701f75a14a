// Counter-based random numbers for generated worlds: the i-th number of a
// stream is a hash of (seed, stream, i), SplitMix64's finaliser applied to
// their mix, so a world depends on its seed only — no global state, the
// same numbers on every machine (integer arithmetic, then one exact
// conversion to a double in [0, 1)). Each generator draws from streams of
// its own (one per element or piece of furniture), so adding a draw to one
// element leaves the others' numbers as they were.
#pragma once

#include <cstdint>

namespace proxsim {

class KeyedRandom {
 public:
  KeyedRandom(std::uint64_t seed, std::uint64_t stream) : seed_(seed), stream_(stream) {}

  /// The next uniform number in [0, 1).
  double Uniform() {
    const std::uint64_t bits = Mix(Mix(seed_ ^ 0x9e3779b97f4a7c15ull) ^ Mix(stream_ + 0x632be59bd9b4e019ull) ^ counter_++);
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
  }
  /// Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  /// A whole number in [lo, hi], each equally likely.
  int Integer(int lo, int hi) { return lo + static_cast<int>(Uniform() * (hi - lo + 1)); }

  /// A seed of its own for each (seed, a, b): worlds of two kinds or two
  /// difficulties drawn from one user seed share no numbers.
  static std::uint64_t MixSeed(std::uint64_t seed, std::uint64_t a, std::uint64_t b) {
    return Mix(Mix(seed ^ 0xd1b54a32d192ed03ull) ^ Mix(a + 0x8cb92ba72f3d8dd7ull) ^ Mix(b + 0x52dce729da3ed9b5ull));
  }

 private:
  static std::uint64_t Mix(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  std::uint64_t seed_;
  std::uint64_t stream_;
  std::uint64_t counter_ = 0;
};

}  // namespace proxsim
