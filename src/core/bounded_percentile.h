// Order statistics (a percentile, the k-th smallest, the largest) of a stream
// of floats too long to hold: the terrain score's per-cell elevation errors,
// one per measured cell of a walk of any length. The values go to a scratch
// file (spill_file.h) a chunk at a time; the k-th smallest is then found by
// radix selection on the floats' bit patterns, read in value order: the
// values are counted by their high 16 bits as they come (a fixed histogram),
// which names the bucket holding rank k, and one pass over the file counts
// that bucket's values by their low 16 bits, which names the value itself.
// Memory: two 65 536-bin histograms and two chunks, whatever the count.
//
// Exact: Nth(k) is the value std::nth_element puts at position k, and
// Percentile(q) numpy's default (linear) percentile, computed as the terrain
// score always did. Zeros of either sign count as +0; NaN has no rank and is
// refused (std::invalid_argument).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/spill_file.h"

namespace proxsim {

class BoundedPercentile {
 public:
  /// The values go to this many at a time to the scratch file (and are read back so).
  static constexpr std::size_t kChunkValues = 16384;

  /// `what` names the values in a scratch file's error messages.
  explicit BoundedPercentile(std::string what);

  void Add(float value);
  std::size_t count() const { return count_; }
  /// The largest value; count() > 0.
  float max() const;
  /// The k-th smallest value (k = 0: the smallest); k < count().
  float Nth(std::size_t k) const;
  /// The q-th quantile (q in [0, 1]), linear between the order statistics
  /// around rank q·(count − 1) (numpy's default); count() > 0.
  double Percentile(double q) const;

 private:
  static constexpr std::size_t kBins = std::size_t{1} << 16;

  // every value, in the order added: the scratch file, then the chunk not yet in it
  template <class Visit>
  void ForEach(Visit&& visit) const;

  SpillFile file_;
  std::vector<float> tail_;
  std::size_t count_ = 0;
  std::uint32_t max_key_ = 0;
  std::vector<std::uint64_t> high_counts_;  // kBins: the values by the high 16 bits of their key
};

}  // namespace proxsim
