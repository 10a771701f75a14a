// The C++ core of proxsim.VecWalkEnv (python/proxsim/vec_walk_env.py): N
// episodes of WalkEnv's task stepped together, their simulations shared out
// over `threads` threads (core/parallel.h) with the GIL released, the
// observations, rewards and flags written straight into NumPy arrays with a
// leading N axis.
//
// The task is WalkEnv's (python/proxsim/walk_env.py), computed with the same
// floating-point operations in the same order, so that env i of a
// VecWalkEnv gives exactly the numbers of a WalkEnv reset with the same seed
// and given the same actions (tests/python/test_vec_walk_env.py):
//   observation (float32): per sensor [d_m, detected, fresh], then
//     [pelvis x_m, pelvis y_m, yaw_rad, gait_phase, stopped, distance_walked_m]
//     (yaw_rad as radians(degrees(yaw)), the round trip WalkEnv's takes);
//   action [walk, stride_m]: walk >= 0.5 walks, < 0.5 stops; the stride is
//     clipped to [min_stride_m, max_stride_m] and set every step;
//   reward: the metres gained toward the path's last waypoint, minus
//     collision_penalty at a new collision and fall_penalty at a fall;
//   terminated: collided, fell or reached its goal; truncated: the episode's
//     time ran out.
// Auto-reset is Gymnasium's "next step" mode: the step after an episode ended
// resets that environment (its action ignored) and returns the first
// observation of its next episode with reward 0 and both flags false.
// Seeds: environment i's episodes are seeded s_i, s_i + N, s_i + 2N, …: s_i is
// what reset(seeds) gives it, or the scenario's seed + i before any.
#pragma once

#include <pybind11/pybind11.h>

namespace proxsim {

/// Adds proxsim._core.VecWalkCore to `module`.
void BindVecWalkEnv(pybind11::module_& module);

}  // namespace proxsim
