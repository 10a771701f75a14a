// The benchmark's world and rays (`proxsim bench`, docs/performance.md): the
// dining room of scene/builtin_scenes.cc rebuilt from closed triangle meshes
// only, tessellated finely enough to reach a target triangle count, with
// clutter on the floor and the table; and the ray sets every engine casts.
// Everything is a deterministic function of its arguments (a hash of the
// index, no random engine), so every engine and every run sees the same data.
//
// Frames: W world only (every vertex and ray is in W).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "scenario/scenario.h"
#include "raycast/ray_caster.h"
#include "scene/scene.h"

namespace proxsim::bench {

/// One closed, outward-oriented triangle mesh in W (a wall panel, a chair leg, a ball).
struct BenchObject {
  std::string name;
  std::shared_ptr<const TriangleMesh> mesh;  ///< vertices in W
  bool ground = false;                       ///< the feet stand on it (SceneObject::ground)
};

struct BenchScene {
  std::vector<BenchObject> objects;
  std::size_t triangle_count = 0;
  std::size_t vertex_count = 0;
  double cell_m = 0;  ///< tessellation cell edge of the furniture and walls
};

/// The dining room at about `target_triangles` triangles (within a few percent
/// above 5k): about 70 % in the tessellated room and furniture, the rest in
/// clutter balls kept off the robot's corridor |y| < 0.5 m.
BenchScene MakeBenchDiningRoom(std::size_t target_triangles);

/// The scene as proxsim objects (one Mesh object per BenchObject, identity pose).
Scene ToScene(const BenchScene& scene);

/// Incoherent sensor rays: origins uniform in the room at 0.05–0.6 m height,
/// directions uniform over the forward (+x) hemisphere, range 2 m.
std::vector<Ray> IncoherentRays(std::size_t count, std::uint64_t seed);

/// Coherent lidar-like fans: groups of `fan_rays` rays sharing an origin (as
/// above), spread over 60° of azimuth at one elevation; range 2 m.
std::vector<Ray> FanRays(std::size_t count, std::size_t fan_rays, std::uint64_t seed);

/// The heavy scenario (docs/performance.md), in the given scene: the built-in biped
/// walking 4.5 m along +x at 1 kHz for `duration_s`, with `mounts`
/// ultrasonic sensors on its legs, each a beam of `rays_per_mount` rays in a
/// 25° cone (BeamSpec: the rays share the sensor's origin).
Scenario HeavyScenario(const BenchScene& scene, int mounts, int rays_per_mount, double duration_s);

/// The paper's walk with a VL53L5CX (8x8 zones of 4 rays) on each shin
/// instead of its four single-ray sensors, read at `rate_hz` (0: every sample),
/// with the stop rule's floor margin of data/scenarios/multizone_shins.yaml.
Scenario ZonedPaperScenario(double rate_hz);

}  // namespace proxsim::bench
