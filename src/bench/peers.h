// The engines `proxsim bench` races proxsim against, on the same triangles and
// the same rays: bare Embree (no instancing, no sensor model), Bullet's
// btCollisionWorld::rayTest on one btBvhTriangleMeshShape, and MuJoCo's mj_ray
// on one mesh geom per object. Each answers a batch of rays with the distance
// of the first hit within the ray's range (+inf on a miss).
//
// Bare Embree is the one file outside src/raycast that includes Embree: it is
// a peer under test, not part of proxsim's pipeline.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "bench/bench_scene.h"
#include "raycast/ray_caster.h"

namespace proxsim::bench {

/// How bare Embree is called.
enum class EmbreeCall {
  kSingle,    ///< rtcIntersect1 per ray
  kPacket4,   ///< rtcIntersect4 over consecutive rays
  kPacket8,   ///< rtcIntersect8
  kPacket16,  ///< rtcIntersect16
  kStream,    ///< rtcIntersect1M over blocks of 256 rays, coherent flag
};
const char* EmbreeCallName(EmbreeCall call);

class RayPeer {
 public:
  virtual ~RayPeer() = default;
  /// distances[i] = first hit of rays[i] within its range, +inf on a miss.
  virtual void Cast(std::span<const Ray> rays, std::span<float> distances, int threads) = 0;
  /// Seconds spent building the acceleration structure.
  virtual double build_s() const = 0;
  /// Bytes held by the engine for the scene (its own accounting where it has one).
  virtual std::size_t bytes() const = 0;
};

/// Bare Embree: one scene, one triangle geometry per object, high build quality.
/// `robust` sets RTC_SCENE_FLAG_ROBUST (proxsim's choice) instead of Embree's default.
class EmbreePeer : public RayPeer {
 public:
  EmbreePeer(const BenchScene& scene, bool robust);
  ~EmbreePeer() override;
  void set_call(EmbreeCall call) { call_ = call; }
  void Cast(std::span<const Ray> rays, std::span<float> distances, int threads) override;
  double build_s() const override { return build_s_; }
  std::size_t bytes() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  EmbreeCall call_ = EmbreeCall::kSingle;
  double build_s_ = 0;
};

/// Bullet, or null with `why` set when it is not built in.
std::unique_ptr<RayPeer> MakeBulletPeer(const BenchScene& scene, std::string* why);
/// MuJoCo, or null with `why` set when it is not built in or cannot load the scene.
std::unique_ptr<RayPeer> MakeMujocoPeer(const BenchScene& scene, std::string* why);

/// Version strings of the peers ("unavailable" when not built in).
std::string BulletVersion();
std::string MujocoVersion();
std::string EmbreeVersion();

}  // namespace proxsim::bench
