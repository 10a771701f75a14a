#include "core/bounded_percentile.h"

#include <bit>
#include <cassert>
#include <cmath>
#include <stdexcept>

namespace proxsim {

namespace {

// A float's bits as an unsigned key in the floats' order: positive ones with
// the sign bit set, negative ones inverted (the larger magnitude, the smaller key).
std::uint32_t Key(float value) {
  if (value == 0.0f) value = 0.0f;  // −0 is +0
  const auto bits = std::bit_cast<std::uint32_t>(value);
  return (bits & 0x80000000u) != 0 ? ~bits : bits | 0x80000000u;
}

float Value(std::uint32_t key) {
  return std::bit_cast<float>((key & 0x80000000u) != 0 ? key & 0x7FFFFFFFu : ~key);
}

// The bin of `counts` holding rank k (0-based), and k's rank within it.
std::pair<std::size_t, std::uint64_t> BinOfRank(const std::vector<std::uint64_t>& counts, std::uint64_t k) {
  for (std::size_t bin = 0; bin < counts.size(); ++bin) {
    if (k < counts[bin]) return {bin, k};
    k -= counts[bin];
  }
  assert(false && "rank beyond the count");
  return {counts.size() - 1, 0};
}

}  // namespace

BoundedPercentile::BoundedPercentile(std::string what) : file_(std::move(what)), high_counts_(kBins, 0) {
  tail_.reserve(kChunkValues);
}

void BoundedPercentile::Add(float value) {
  if (std::isnan(value)) throw std::invalid_argument("BoundedPercentile: NaN has no rank");
  const std::uint32_t key = Key(value);
  ++high_counts_[key >> 16];
  max_key_ = count_ == 0 ? key : std::max(max_key_, key);
  ++count_;
  tail_.push_back(value);
  if (tail_.size() < kChunkValues) return;
  file_.Append(std::string_view(reinterpret_cast<const char*>(tail_.data()), tail_.size() * sizeof(float)));
  tail_.clear();
}

float BoundedPercentile::max() const {
  assert(count_ > 0);
  return Value(max_key_);
}

template <class Visit>
void BoundedPercentile::ForEach(Visit&& visit) const {
  std::vector<float> chunk(kChunkValues);
  const std::uint64_t spilled = file_.size() / sizeof(float);
  for (std::uint64_t at = 0; at < spilled; at += kChunkValues) {
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunkValues, spilled - at));
    file_.ReadAt(at * sizeof(float), chunk.data(), n * sizeof(float));
    for (std::size_t i = 0; i < n; ++i) visit(chunk[i]);
  }
  for (float value : tail_) visit(value);
}

float BoundedPercentile::Nth(std::size_t k) const {
  assert(k < count_);
  // the high bits' bin holding rank k, then that bin's values by their low bits
  const auto [high, k_in_high] = BinOfRank(high_counts_, k);
  std::vector<std::uint64_t> low_counts(kBins, 0);
  ForEach([&, high = high](float value) {
    const std::uint32_t key = Key(value);
    if ((key >> 16) == high) ++low_counts[key & 0xFFFFu];
  });
  const std::size_t low = BinOfRank(low_counts, k_in_high).first;
  return Value(static_cast<std::uint32_t>(high << 16 | low));
}

double BoundedPercentile::Percentile(double q) const {
  assert(count_ > 0);
  const double rank = q * static_cast<double>(count_ - 1);
  const auto lo = static_cast<std::size_t>(std::floor(rank));
  const double at_lo = Nth(lo);
  const double at_hi = lo + 1 < count_ ? Nth(lo + 1) : at_lo;
  return at_lo + (rank - static_cast<double>(lo)) * (at_hi - at_lo);
}

}  // namespace proxsim
