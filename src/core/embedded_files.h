// Files compiled into the binary (the built-in robot and scenarios), so that
// proxsim runs the paper's experiment from any directory. The table is
// generated at build time by cmake/embed_files.cmake.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace proxsim {

/// Embedded file contents keyed by path relative to the source tree,
/// e.g. "data/robots/biped.urdf".
const std::map<std::string, std::string_view>& EmbeddedFiles();

}  // namespace proxsim
