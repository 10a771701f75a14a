// The terrain score's end in bounded memory (issue 23): BoundedPercentile's
// order statistics are exactly std::nth_element's (random data with ties, the
// edges of its bins, zeros, infinities, more values than a chunk), and neither
// it nor the score's readers of the track hold the whole stream: the heap in
// use (glibc's mallinfo2, allocation counts, not resident memory) grows by a
// bounded amount while they take far more values than that bound.
#include <gtest/gtest.h>

#include <malloc.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "core/bounded_percentile.h"
#include "knowledge/terrain_map.h"
#include "output/corridor.h"
#include "output/terrain_score.h"

namespace proxsim {
namespace {

// What the terrain score computed before (a copy of every value, nth_element):
// numpy's linear percentile.
double ReferencePercentile(std::vector<float> values, double q) {
  const std::size_t n = values.size();
  const double rank = q * static_cast<double>(n - 1);
  const auto lo = static_cast<std::size_t>(std::floor(rank));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(lo), values.end());
  const double at_lo = values[lo];
  const double at_hi = lo + 1 < n ? *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(lo) + 1, values.end()) : at_lo;
  return at_lo + (rank - static_cast<double>(lo)) * (at_hi - at_lo);
}

float ReferenceNth(std::vector<float> values, std::size_t k) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

// Every order statistic at the ranks given, the percentiles, and the largest, bit for bit.
void ExpectSameAsNthElement(const std::vector<float>& values, const std::vector<std::size_t>& ranks) {
  BoundedPercentile bounded("test values");
  for (float v : values) bounded.Add(v);
  ASSERT_EQ(bounded.count(), values.size());
  for (std::size_t k : ranks) {
    const float expected = ReferenceNth(values, k);
    // zeros of either sign are one value (the score's are |error|: never −0)
    EXPECT_EQ(std::bit_cast<std::uint32_t>(bounded.Nth(k)), std::bit_cast<std::uint32_t>(expected == 0 ? 0.0f : expected))
        << "rank " << k << " of " << values.size() << ": " << bounded.Nth(k) << " vs " << expected;
  }
  for (double q : {0.0, 0.05, 0.25, 0.5, 0.9, 0.95, 0.99, 1.0}) {
    const double expected = ReferencePercentile(values, q), got = bounded.Percentile(q);
    EXPECT_TRUE(got == expected || (std::isnan(got) && std::isnan(expected))) << "q " << q << ": " << got << " vs " << expected;
    EXPECT_EQ(std::signbit(got), std::signbit(expected == 0 ? 0.0 : expected)) << "q " << q;
  }
  EXPECT_EQ(bounded.max(), *std::max_element(values.begin(), values.end()));
}

std::vector<std::size_t> AllRanks(std::size_t n) {
  std::vector<std::size_t> ranks(n);
  for (std::size_t k = 0; k < n; ++k) ranks[k] = k;
  return ranks;
}

TEST(BoundedPercentile, RandomErrorsWithTiesOverSeveralChunksGiveNthElementsValues) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> error_m(0.0f, 0.05f);
  std::uniform_int_distribution<int> pick(0, 9);
  // errors as the score has them: many exact ties (0, a few mm) among continuous ones
  std::vector<float> values;
  const std::size_t n = 3 * BoundedPercentile::kChunkValues + 123;
  for (std::size_t i = 0; i < n; ++i) {
    const int p = pick(rng);
    values.push_back(p == 0 ? 0.0f : p == 1 ? 0.002f : p == 2 ? 0.003f : error_m(rng));
  }
  std::vector<std::size_t> ranks = {0, 1, n / 2, n - 2, n - 1};
  for (int i = 0; i < 200; ++i) ranks.push_back(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng));
  ExpectSameAsNthElement(values, ranks);
}

TEST(BoundedPercentile, TheEdgesOfItsBinsAndOfTheFloats) {
  // neighbours across a high-bits bin's edge: ...FFFF and the next bin's ...0000
  std::vector<float> edges;
  for (std::uint32_t bits : {0x3C23FFFFu, 0x3C240000u, 0x3C23FFFEu, 0x3C240001u, 0x3C24FFFFu, 0x3C250000u}) {
    edges.push_back(std::bit_cast<float>(bits));
    edges.push_back(std::bit_cast<float>(bits));  // and tied
  }
  ExpectSameAsNthElement(edges, AllRanks(edges.size()));
  // the ranks around the 95th percentile in two bins: 19 values in one, 1 in the next
  std::vector<float> split(19, std::bit_cast<float>(0x3C23FFFFu));
  split.push_back(std::bit_cast<float>(0x3C240000u));
  ExpectSameAsNthElement(split, AllRanks(split.size()));
  // zeros of both signs, negatives, denormals, the largest floats, infinities
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> odd = {0.0f, -0.0f, -1.0f, 1.0f, std::numeric_limits<float>::denorm_min(),
                                  -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::max(),
                                  std::numeric_limits<float>::lowest(), inf, -inf, 0.0f, -2.5f, 2.5f, 1e-30f};
  ExpectSameAsNthElement(odd, AllRanks(odd.size()));
  // a single value; every value equal (one bin holds them all), past a chunk
  ExpectSameAsNthElement({0.25f}, {0});
  ExpectSameAsNthElement(std::vector<float>(BoundedPercentile::kChunkValues + 5, 0.01f), {0, 7, BoundedPercentile::kChunkValues + 4});
  // the largest infinite: the percentile between a finite value and it is infinite
  ExpectSameAsNthElement({1.0f, inf}, {0, 1});
}

TEST(BoundedPercentile, RefusesNaN) {
  BoundedPercentile bounded("test values");
  EXPECT_THROW(bounded.Add(std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
  EXPECT_EQ(bounded.count(), 0u);
}

#if !defined(__SANITIZE_ADDRESS__)
// The heap in use (small blocks and mapped ones), from glibc's own counts.
std::size_t HeapInUseBytes() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
}

TEST(BoundedPercentile, HoldsAFixedAmountWhateverTheCount) {
  // 4 M values are 16 MB if kept; held: two 65 536-bin histograms and two chunks
  constexpr std::size_t kBound = 3u << 20;
  const std::size_t before = HeapInUseBytes();
  std::size_t peak = before;
  {
    BoundedPercentile bounded("test values");
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<float> error_m(0.0f, 0.1f);
    for (std::size_t i = 0; i < (4u << 20); ++i) {
      bounded.Add(error_m(rng));
      if (i % 65536 == 0) peak = std::max(peak, HeapInUseBytes());
    }
    EXPECT_GT(bounded.Percentile(0.95), 0.09);
    peak = std::max(peak, HeapInUseBytes());
  }
  EXPECT_LT(peak - before, kBound) << "the values are held in memory";
}

// A long track made on the fly: `n` points a centimetre apart, pacing to and
// fro along 2 m (so that the corridor stays small), the heap checked as it goes.
class PacingTrack : public TrackReader {
 public:
  explicit PacingTrack(std::size_t n) : n_(n) {}
  void ForEachTrackPoint(const std::function<void(const TrackPoint&)>& visit) const override {
    for (std::size_t i = 0; i < n_; ++i) {
      TrackPoint point;
      point.t_s = 0.02 * static_cast<double>(i);
      const std::size_t along = i % 400;
      point.p_W_pelvis = Vec2(0.01 * static_cast<double>(along < 200 ? along : 400 - along), 0.0);
      point.p_W_front = point.p_W_pelvis + Vec2(0.1, 0.0);
      visit(point);
      if (i % 16384 == 0) peak_bytes = std::max(peak_bytes, HeapInUseBytes());
    }
  }
  mutable std::size_t peak_bytes = 0;

 private:
  std::size_t n_;
};

TEST(TerrainScoreStream, TheCorridorAndTheScoreStreamTheTrackRatherThanHoldIt) {
  // 500 000 points are 32 MB held; a corridor over 2 m and a map with nothing in it hold little
  constexpr std::size_t kPoints = 500000, kBound = 4u << 20;
  const SensorSpec ideal = SensorSpec::Preset(SensorType::kIdeal);
  const TerrainMap map(TerrainMapConfig{}, {ideal}, {true});
  PacingTrack track(kPoints);
  const std::size_t before = HeapInUseBytes();
  track.peak_bytes = before;
  const Corridor corridor(track, map.last_position(), 0.02);
  EXPECT_GT(corridor.cell_count(), 2000u) << "2 m by 0.6 m in 2 cm cells";
  TerrainScorer scorer(map, track, {}, 0.6, corridor);
  const nlohmann::json score = scorer.Json();
  EXPECT_EQ(score["elevation_error"]["cells"].get<std::size_t>(), 0u);
  EXPECT_LT(track.peak_bytes - before, kBound) << "the track is held in memory";
}
#endif

}  // namespace
}  // namespace proxsim
