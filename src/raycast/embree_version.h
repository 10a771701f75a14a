// The Embree library's version, kept behind the ray caster like the rest of
// Embree (summary.json's versions).
#pragma once

#include <string>

namespace proxsim {

/// Embree's version string, e.g. "3.13.5".
std::string EmbreeVersion();

}  // namespace proxsim
