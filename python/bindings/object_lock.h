// One Python-facing object's mutex, taken for a whole call: Simulation's and
// VecWalkCore's calls release the GIL while they step, so without it a
// second Python thread could reset or step the same object under them.
#pragma once

#include <pybind11/pybind11.h>

#include <mutex>

namespace proxsim {

/// Takes `mutex` for the current call. Called with the GIL held: when another
/// thread holds the mutex (inside a step, GIL released), waits for it with the
/// GIL released, or the two threads would deadlock.
class ObjectLock {
 public:
  explicit ObjectLock(std::mutex& mutex) : lock_(mutex, std::try_to_lock) {
    if (!lock_.owns_lock()) {
      pybind11::gil_scoped_release release;
      lock_.lock();
    }
  }

 private:
  std::unique_lock<std::mutex> lock_;
};

}  // namespace proxsim
