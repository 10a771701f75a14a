// The bounds every input is held to before a third-party parser (Assimp,
// urdfdom's TinyXML, rapidjson inside Assimp) sees it. Those parsers recurse
// once per level of nesting and trust the sizes a file declares, so a small
// hostile file could overflow the stack or ask for gigabytes; proxsim checks
// these limits itself first and refuses the file with exit 2, naming the
// limit (docs/trust.md, "Bounded input"). Generous for real robots and scenes.
#pragma once

#include <cstddef>
#include <cstdint>

namespace proxsim {

/// Elements inside elements (XML: URDF, Collada) or arrays and objects inside
/// each other (JSON: glTF), and the depth of a glTF or Collada node tree.
inline constexpr int kMaxNestingDepth = 256;

/// Bytes of one mesh file (and of each file it refers to, glTF buffers say).
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t{1} << 30;  // 1 GiB

/// Vertices or faces a mesh file may declare (OFF and PLY counts, glTF accessors).
inline constexpr std::uint64_t kMaxDeclaredElements = 100'000'000;

/// Bytes of a URDF file and its links and joints.
inline constexpr std::uintmax_t kMaxUrdfBytes = std::uintmax_t{64} << 20;  // 64 MiB
inline constexpr std::size_t kMaxUrdfLinks = 200'000;

/// Bodies of an MJCF robot (its file and its includes, counted before MuJoCo
/// compiles it): a humanoid has tens; MuJoCo's compile grows faster than the
/// count (20 000 bodies took 105 s and 1.8 GB).
inline constexpr std::size_t kMaxMjcfBodies = 2'000;

/// Any coordinate of the scene (object positions, mesh vertices after scaling
/// and placing, path waypoints, the robot's start): Embree casts rays in single
/// precision, whose spacing at 1e5 m is 7.8 mm — more than a proximity sensor's
/// resolution — and which refuses rays beyond about 1.8e18 m outright.
inline constexpr double kMaxCoordinate_m = 1e5;

}  // namespace proxsim
