// What Embree is and how it is set up for this process, kept behind the ray
// caster like the rest of Embree (summary.json's versions, `proxsim bench`).
#pragma once

#include <string>

namespace proxsim {

/// Embree's version string, e.g. "3.13.5".
std::string EmbreeVersion();

/// The environment variable whose value is passed to rtcNewDevice as its
/// configuration string, e.g. "isa=sse4.2" to force Embree's SSE4.2 code path
/// on a CPU that has AVX2 or AVX-512 (docs/performance.md, docs/trust.md).
inline constexpr const char* kEmbreeConfigVariable = "PROXSIM_EMBREE_CONFIG";

/// The device configuration every Embree device of this process is created
/// with: the value of PROXSIM_EMBREE_CONFIG, or "" (Embree's defaults: it
/// picks the widest code path the CPU has).
std::string EmbreeDeviceConfig();

}  // namespace proxsim
