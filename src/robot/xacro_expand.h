// Xacro robots expanded by ROS's own `xacro` (PyPI's package, pinned in
// python/requirements.txt and installed into .venv/ by scripts/install-deps.sh),
// never by a hand-written expander: proxsim runs `xacro FILE` and reads the
// URDF it prints. Which xacro: the PROXSIM_XACRO environment variable, else
// the .venv's found at configure time (PROXSIM_XACRO_DEFAULT), else `xacro` on PATH.
#pragma once

#include <string>

namespace proxsim {

/// The URDF text `xacro` prints for the file at `path` (macros, properties,
/// includes and `${…}` expressions expanded). Throws InputError naming the
/// file, the xacro run and its own message when it cannot run or fails.
std::string ExpandXacro(const std::string& path);

/// The xacro executable ExpandXacro runs.
std::string XacroExecutable();

}  // namespace proxsim
