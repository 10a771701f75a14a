#include "core/parallel.h"

#include <algorithm>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/parallel_invoke.h>
#include <oneapi/tbb/task_arena.h>

namespace proxsim {

struct ParallelRunner::Arena {
  explicit Arena(int threads) : arena(threads) {}
  mutable tbb::task_arena arena;
};

ParallelRunner::ParallelRunner(int threads) : threads_(std::max(1, threads)) {
  if (threads_ > 1) arena_ = std::make_unique<Arena>(threads_);
}

ParallelRunner::~ParallelRunner() = default;

void ParallelRunner::For(std::size_t count, std::size_t grain,
                         const std::function<void(std::size_t, std::size_t)>& body) const {
  if (count == 0) return;
  if (!arena_ || count <= grain) {
    body(0, count);
    return;
  }
  arena_->arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, std::max<std::size_t>(1, grain)),
                      [&](const tbb::blocked_range<std::size_t>& range) { body(range.begin(), range.end()); });
  });
}

void ParallelRunner::Invoke(const std::function<void()>& a, const std::function<void()>& b) const {
  if (!arena_) {
    a();
    b();
    return;
  }
  arena_->arena.execute([&] { tbb::parallel_invoke(a, b); });
}

}  // namespace proxsim
