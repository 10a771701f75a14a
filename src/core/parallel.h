// Fork-join over a range of indices on a fixed number of threads, for the
// work of one sample step (a batch of rays, the sensors of a sample).
//
// Why TBB and not OpenMP: a sample at 1 kHz is a fraction of a millisecond
// of work, forked a thousand times a second. OpenMP's barrier waits for every
// thread of the team, so when the machine is busy (another run, a compiler)
// and one thread is descheduled, every fork waits a whole scheduler slice:
// measured on 2 cores at load 5, the 64-sensor beam scenario ran 15× slower
// on 2 threads than on 1. TBB's work stealing lets the threads that are
// running take all the work, and it is the pool Embree already uses for its
// builds, so the process keeps one set of threads instead of two competing.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

namespace proxsim {

class ParallelRunner {
 public:
  /// Runs work on up to `threads` threads (>= 1); 1 runs it on the caller alone.
  explicit ParallelRunner(int threads);
  ~ParallelRunner();
  ParallelRunner(const ParallelRunner&) = delete;
  ParallelRunner& operator=(const ParallelRunner&) = delete;

  int threads() const { return threads_; }

  /// Calls body(begin, end) over [0, count) in chunks of about `grain`
  /// indices, possibly at once on several threads; returns when all are done.
  /// Which thread takes which chunk varies, so body must not depend on it.
  void For(std::size_t count, std::size_t grain, const std::function<void(std::size_t, std::size_t)>& body) const;

  /// Runs a and b, at once when there are threads for it; returns when both are done.
  void Invoke(const std::function<void()>& a, const std::function<void()>& b) const;

 private:
  struct Arena;
  int threads_ = 1;
  std::unique_ptr<Arena> arena_;
};

}  // namespace proxsim
