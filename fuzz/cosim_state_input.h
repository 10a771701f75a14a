// The co-simulation state a fuzz input stands for (fuzz/fuzz_cosim_state.cc,
// replayed by FuzzRegressionTest.CosimState): its bytes read as native
// doubles, [x, y, z] of the root link, a quaternion (w, x, y, z) — or, when
// the input's length is odd, a 3×3 rotation matrix row by row — then every
// remaining value a joint (as many as the input holds, so that too few and
// too many are both tried). Any input must be taken, or refused with an
// InputError naming the fault (issue 40: a root link at x = 5e7 m once
// allocated 8.5 GB in the first step).
#pragma once

#include <cstring>
#include <string_view>
#include <vector>

#include "gait/external_drive.h"

namespace proxsim {

inline ExternalState FuzzedExternalState(std::string_view bytes) {
  std::vector<double> v(bytes.size() / sizeof(double));
  if (!v.empty()) std::memcpy(v.data(), bytes.data(), v.size() * sizeof(double));
  const auto at = [&](std::size_t i) { return i < v.size() ? v[i] : (i == 3 ? 1.0 : 0.0); };
  ExternalState state;
  state.p_WP = Vec3(at(0), at(1), at(2));
  std::size_t next = 7;
  if (bytes.size() % 2 == 1) {
    Rotation R;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R(i, j) = at(3 + 3 * i + j);
    state.R_WP = R;
    next = 12;
  } else {
    state.quat_wxyz = Eigen::Vector4d(at(3), at(4), at(5), at(6));
  }
  for (std::size_t i = next; i < v.size(); ++i) state.q.push_back(v[i]);
  return state;
}

}  // namespace proxsim
