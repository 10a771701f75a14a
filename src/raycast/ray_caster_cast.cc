// Casting a batch of rays: packets of consecutive rays, each into the world
// and then, for the rays that see it, into each robot body up to the world hit;
// the hit mapped back to its object, with its normal in W. Large batches are
// shared out over the threads on packet boundaries.
#include "raycast/ray_caster_internal.h"

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <functional>
#include <span>

namespace proxsim {

namespace {

using raycast_internal::Body;
using raycast_internal::GeomRecord;

/// Batches at least this large are spread over the threads.
constexpr std::size_t kParallelBatchRays = 512;

/// Sets flush-to-zero and denormals-are-zero (Embree's recommendation) for
/// the life of the guard, then puts the thread's MXCSR back as it was.
class DenormalModeGuard {
 public:
  DenormalModeGuard() : saved_csr_(_mm_getcsr()) {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
  }
  ~DenormalModeGuard() { _mm_setcsr(saved_csr_); }
  DenormalModeGuard(const DenormalModeGuard&) = delete;
  DenormalModeGuard& operator=(const DenormalModeGuard&) = delete;

 private:
  unsigned int saved_csr_;
};

/// Rays go to Embree in packets of this many consecutive rays: a beam's rays
/// share an origin and sit side by side in the batch, so a packet's rays
/// walk the same BVH nodes; for incoherent rays Embree's packet kernel costs
/// about what its single-ray one does (`proxsim bench` measures both).
constexpr std::size_t kPacketRays = 8;

/// Where a packet's rays are cast.
struct CastScenes {
  RTCScene world = nullptr;      ///< the world's top-level scene, or the world body's own (direct)
  int direct_body = -1;          ///< the body of `world` when it is direct, else -1 (hits carry the instance)
  std::span<const int> robot_candidates;  ///< the robot bodies the batch may meet (RobotCandidates), each cast on its own
  RTCScene moving = nullptr;     ///< the moving objects' top-level scene; null when there are none
  // each scene's bodies by instance ID
  const std::vector<int>* world_bodies = nullptr;
  const std::vector<int>* moving_bodies = nullptr;
  const std::vector<Eigen::Vector4d>* moving_spheres_W = nullptr;  ///< the moving bodies' bounding spheres
  std::function<void()> commit_moving;  ///< commits `moving` if it moved (before a cast into it)
  bool test_spheres = false;            ///< cast into `moving` only the packets with a ray that may meet one
};

// A batch tests its rays against the moving objects' spheres, rather than
// have their scene committed, while it takes at most this many tests: a test
// costs ~3.5 ns, a commit of 50 instances ~40 µs (docs/performance.md), what
// about 10 000 tests do.
constexpr std::size_t kMaxSphereTests = 4096;

// A ray that passes this far outside a moving body's bounding sphere cannot
// meet it: Embree's float transforms and bounds err by microns, not this.
constexpr double kSphereSlack_m = 1e-3;

/// Whether `lane`'s ray, up to its nearest hit so far (tfar), passes within
/// one of `spheres_W` (centre, radius; an infinite radius always).
bool MayMeetSphere(const RTCRayHit8& packet, std::size_t lane, const std::vector<Eigen::Vector4d>& spheres_W) {
  const Vec3 origin(packet.ray.org_x[lane], packet.ray.org_y[lane], packet.ray.org_z[lane]);
  const Vec3 direction(packet.ray.dir_x[lane], packet.ray.dir_y[lane], packet.ray.dir_z[lane]);
  const double reach = static_cast<double>(packet.ray.tfar[lane]) * (1 + 1e-6) + kSphereSlack_m;
  const double dd = direction.squaredNorm();
  for (const Eigen::Vector4d& sphere : spheres_W) {
    const Vec3 to_centre = sphere.head<3>() - origin;
    // the segment's point nearest the centre
    const double t = std::clamp(to_centre.dot(direction) / dd, 0.0, reach);
    const double within_m = sphere.w() + kSphereSlack_m;
    if ((to_centre - t * direction).squaredNorm() <= within_m * within_m) return true;
  }
  return false;
}

/// Maps the hit of `lane` to the body and its shape; Ng from B to W, unit.
/// `instance_bodies`: the cast scene's bodies by instance ID (unused when `direct_body` >= 0).
void MapHit(const RTCRayHit8& packet, std::size_t lane, int direct_body, const std::vector<int>& instance_bodies,
            const std::vector<std::unique_ptr<Body>>& bodies, Hit* hit) {
  const unsigned int inst = packet.hit.instID[0][lane];
  if (packet.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID || (direct_body < 0 && inst == RTC_INVALID_GEOMETRY_ID)) {
    *hit = Hit{};  // a miss
    return;
  }
  const Body& body = *bodies[static_cast<std::size_t>(direct_body >= 0 ? direct_body : instance_bodies[inst])];
  const GeomRecord& geom = *body.geoms[packet.hit.geomID[lane]];
  const Vec3f normal_B = Vec3f(packet.hit.Ng_x[lane], packet.hit.Ng_y[lane], packet.hit.Ng_z[lane]).normalized();
  hit->distance_m = packet.ray.tfar[lane];
  hit->normal_W = body.R_WB * normal_B;
  hit->object_id = geom.object_id;
}

// Far below Embree's own bound (FLT_LARGE, 1.844e18), far above the scene's
// coordinate limit (core/input_limits.h).
constexpr float kMaxRayOrigin_m = 1e15f;
const Ray kHarmlessRay{Vec3f::Zero(), Vec3f::UnitX(), 1.0f};

// (a comparison with a NaN is false, and |±inf| is beyond both bounds: each
// test below also refuses the non-finite values)
inline bool RayEmbreeCanTake(const Ray& ray) {
  constexpr float kFinite = std::numeric_limits<float>::max();
  const Vec3f& o = ray.origin_W;
  const Vec3f& d = ray.direction_W;
  // (`&`, not `&&`: every test is cheap, and one branch beats nine)
  return (std::abs(o.x()) < kMaxRayOrigin_m) & (std::abs(o.y()) < kMaxRayOrigin_m) & (std::abs(o.z()) < kMaxRayOrigin_m) &
         (std::abs(d.x()) <= kFinite) & (std::abs(d.y()) <= kFinite) & (std::abs(d.z()) <= kFinite) &
         ((d.x() != 0.0f) | (d.y() != 0.0f) | (d.z() != 0.0f)) & (ray.max_range_m >= 0.0f);
}

// The cone test below errs on the side of a meeting by this much in the
// cosine (rounding in the sums; Embree's own slack is in the spheres' radii).
constexpr double kConeCosSlack = 1e-9;

/// Up to this many candidate bodies are listed (RobotCandidates); a batch
/// that may meet more is tested against the whole robot.
constexpr std::size_t kMaxListedBodies = 32;

/// A batch's candidate robot bodies: a short list kept on the stack (no heap
/// per cast), or the whole robot.
struct RobotCandidateList {
  std::array<int, kMaxListedBodies> listed{};
  std::size_t count = 0;
  const std::vector<int>* whole_robot = nullptr;  ///< set: every body is a candidate
  std::span<const int> bodies() const {
    return whole_robot ? std::span<const int>(*whole_robot) : std::span<const int>(listed.data(), count);
  }
};

/// The robot's bodies (indices into Impl::bodies) that some ray of the batch
/// seeing the robot may meet. When those rays all start at one point (a
/// sensor's beam or zones), they lie in a cone around the mean of their
/// directions, out to the longest ray; a body's bounding sphere that lies
/// outside that cone meets none of them (exact: the sphere holds the body's
/// box, which holds every hit on it). Otherwise every body.
RobotCandidateList RobotCandidates(std::span<const Ray> rays, const std::vector<int>& robot_bodies,
                                   const std::vector<Eigen::Vector4d>& robot_spheres_W) {
  RobotCandidateList out;
  const auto all = [&] {
    out.whole_robot = &robot_bodies;
    return out;
  };
  const Ray* first = nullptr;
  Vec3 axis = Vec3::Zero();
  double longest_m = 0.0;
  // (a ray Embree cannot take is never cast, but is not singled out here: a
  // non-finite origin or direction makes the sums non-finite, and then every
  // body is a candidate; a zero direction or a NaN range is passed over by
  // the comparisons, which are false for NaN)
  for (const Ray& ray : rays) {
    if (!ray.see_robot) continue;  // never cast into the robot
    if (first == nullptr) first = &ray;
    if (ray.origin_W != first->origin_W) return all();
    axis += ray.direction_W.cast<double>();  // (unit: any axis will do, θ is measured from it)
    longest_m = std::max(longest_m, static_cast<double>(ray.max_range_m));
  }
  if (first == nullptr) return out;  // no ray sees the robot: no candidate
  const double axis_norm = axis.norm();
  if (!(axis_norm > 1e-6) || !std::isfinite(axis_norm) || !first->origin_W.allFinite()) return all();
  axis /= axis_norm;
  double cos_half = 1.0;  // the cone's half-angle θ: the widest ray off the axis
  for (const Ray& ray : rays) {
    if (!ray.see_robot) continue;
    const Vec3 d = ray.direction_W.cast<double>();
    cos_half = std::min(cos_half, axis.dot(d) / d.norm());
  }
  if (!(cos_half > 0.0)) return all();  // a half-space or wider: no cut worth its cost
  const double sin_half = std::sqrt(std::max(0.0, 1.0 - cos_half * cos_half));
  const Vec3 apex_W = first->origin_W.cast<double>();
  for (std::size_t slot = 0; slot < robot_spheres_W.size(); ++slot) {
    const Eigen::Vector4d& sphere = robot_spheres_W[slot];
    const Vec3 to_centre = sphere.head<3>() - apex_W;
    const double d_m = to_centre.norm(), r_m = sphere.w();
    bool may_meet = !(d_m > r_m);  // the apex within the sphere (or an unbounded body)
    if (!may_meet && d_m - r_m <= longest_m * (1 + 1e-6)) {
      // within the cone widened by the sphere's angular radius β: the angle
      // φ to its centre at most θ + β, compared by cosines (sin β = r/d)
      const double sin_beta = r_m / d_m, cos_beta = std::sqrt(std::max(0.0, 1.0 - sin_beta * sin_beta));
      const double cos_limit = cos_half * cos_beta - sin_half * sin_beta;  // cos(θ + β), θ + β < π
      may_meet = to_centre.dot(axis) / d_m >= cos_limit - kConeCosSlack;
    }
    if (!may_meet) continue;
    if (out.count == kMaxListedBodies) return all();
    out.listed[out.count++] = robot_bodies[slot];
  }
  return out;
}

/// Casts the lanes in `sees` into one robot body's own scene, each ray moved
/// into the body's frame B (the distance along it is the same in both
/// frames: a rigid motion), and keeps the hits nearer than each lane's
/// nearest so far (the packet's tfar, lowered here). Only the lanes whose
/// segment up to that nearest hit passes through the body's box
/// (Body::box_lo_B, box_hi_B: the slab test, the segment lengthened by the
/// box's slack, which covers the float sums' rounding) are cast, and nothing
/// when no lane does.
///
/// Why no top-level scene of the robot's instances: the robot moves every
/// sample, and committing that scene (~50 000 instructions for the biped's
/// 15 links) cost more than every cast into it of an outcome study's step
/// (docs/performance.md). A ray moved into B here meets the body's triangles
/// and shapes as Embree's instance moved it, in float, but by sums in another
/// order: the two differ in the last bits of a distance on the robot. Every
/// lane takes the same sums, so a lane's answer does not depend on its packet.
void CastIntoRobotBody(const Body& body, const bool sees[kPacketRays], const RTCIntersectContext& context,
                       RTCRayHit8& packet, Hit* hits, std::size_t n) {
  // the lanes moved into B and tested four at a time, in float as Embree's
  // instances moved them (SSE: the same sums on every x86-64 CPU)
  const Eigen::Matrix3f R_BW = body.X_BW.linear().cast<float>();
  const Vec3f p_BW = body.X_BW.translation().cast<float>();
  const Vec3f lo_B = body.box_lo_B.cast<float>(), hi_B = body.box_hi_B.cast<float>();
  RTCRayHit8 local;
  alignas(32) int valid[kPacketRays];
  bool any = false;
  const __m128 slack = _mm_set1_ps(static_cast<float>(raycast_internal::kRobotBoxSlack_m));
  const __m128 widen = _mm_set1_ps(1.0f + 1e-6f);
  for (std::size_t l = 0; l < kPacketRays; l += 4) {
    // (inactive lanes hold a finite ray: the sums are harmless)
    const __m128 o[3] = {_mm_loadu_ps(&packet.ray.org_x[l]), _mm_loadu_ps(&packet.ray.org_y[l]), _mm_loadu_ps(&packet.ray.org_z[l])};
    const __m128 d[3] = {_mm_loadu_ps(&packet.ray.dir_x[l]), _mm_loadu_ps(&packet.ray.dir_y[l]), _mm_loadu_ps(&packet.ray.dir_z[l])};
    const __m128 length = _mm_sqrt_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[1], d[1])), _mm_mul_ps(d[2], d[2])));
    const __m128 tfar = _mm_loadu_ps(&packet.ray.tfar[l]);
    __m128 t_in = _mm_setzero_ps();
    __m128 t_out = _mm_add_ps(_mm_mul_ps(tfar, widen), _mm_div_ps(slack, length));
    float* const org_B[3] = {&local.ray.org_x[l], &local.ray.org_y[l], &local.ray.org_z[l]};
    float* const dir_B[3] = {&local.ray.dir_x[l], &local.ray.dir_y[l], &local.ray.dir_z[l]};
    for (int k = 0; k < 3; ++k) {
      const __m128 r0 = _mm_set1_ps(R_BW(k, 0)), r1 = _mm_set1_ps(R_BW(k, 1)), r2 = _mm_set1_ps(R_BW(k, 2));
      const __m128 o_k = _mm_add_ps(
          _mm_add_ps(_mm_add_ps(_mm_mul_ps(r0, o[0]), _mm_mul_ps(r1, o[1])), _mm_mul_ps(r2, o[2])), _mm_set1_ps(p_BW[k]));
      const __m128 d_k = _mm_add_ps(_mm_add_ps(_mm_mul_ps(r0, d[0]), _mm_mul_ps(r1, d[1])), _mm_mul_ps(r2, d[2]));
      _mm_storeu_ps(org_B[k], o_k);
      _mm_storeu_ps(dir_B[k], d_k);
      // the slab test: a direction component of 0 gives ±inf, or NaN at a face (a meeting, below)
      const __m128 t0 = _mm_div_ps(_mm_sub_ps(_mm_set1_ps(lo_B[k]), o_k), d_k);
      const __m128 t1 = _mm_div_ps(_mm_sub_ps(_mm_set1_ps(hi_B[k]), o_k), d_k);
      t_in = _mm_max_ps(t_in, _mm_min_ps(t0, t1));
      t_out = _mm_min_ps(t_out, _mm_max_ps(t0, t1));
    }
    // not t_in > t_out: a meeting (true also for a NaN: the cast decides)
    const int meets = _mm_movemask_ps(_mm_cmpngt_ps(t_in, t_out));
    for (std::size_t lane = l; lane < l + 4; ++lane) {
      valid[lane] = sees[lane] && (meets >> (lane - l) & 1) ? -1 : 0;
      any = any || valid[lane];
    }
  }
  if (!any) return;
  for (std::size_t lane = 0; lane < kPacketRays; ++lane) {
    local.ray.tnear[lane] = 0.0f;
    local.ray.time[lane] = 0.0f;
    local.ray.tfar[lane] = packet.ray.tfar[lane];
    local.ray.mask[lane] = 0xFFFFFFFFu;
    local.ray.id[lane] = 0;
    local.ray.flags[lane] = 0;
    local.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    local.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext body_context = context;
  rtcIntersect8(valid, body.scene, &body_context, &local);
  for (std::size_t lane = 0; lane < n; ++lane) {
    if (!valid[lane] || local.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID) continue;
    packet.ray.tfar[lane] = local.ray.tfar[lane];
    const GeomRecord& geom = *body.geoms[local.hit.geomID[lane]];
    const Vec3f normal_B = Vec3f(local.hit.Ng_x[lane], local.hit.Ng_y[lane], local.hit.Ng_z[lane]).normalized();
    hits[lane].distance_m = local.ray.tfar[lane];
    hits[lane].normal_W = body.R_WB * normal_B;
    hits[lane].object_id = geom.object_id;
  }
}

/// Casts rays[0..n) (n <= 8) as one packet: into the world, then the lanes
/// that may meet a moving object into theirs, then those that see the robot
/// into each robot body they may meet, each up to its nearest hit so far
/// (Embree only reports a nearer one). Each lane is intersected on its own, so a
/// ray's answer does not depend on the other rays of its packet.
void CastPacket(const CastScenes& scenes, const std::vector<std::unique_ptr<Body>>& bodies, const Ray* rays,
                Hit* hits, std::size_t n) {
  alignas(32) int valid[kPacketRays];
  bool representable[kPacketRays];  // each lane's RayEmbreeCanTake, found once
  RTCRayHit8 packet;
  for (std::size_t lane = 0; lane < kPacketRays; ++lane) {
    // Embree asserts (aborts) on a ray it cannot represent (|origin| beyond
    // ~1.8e18, non-finite values): such a lane is left out and sees nothing.
    // Input checks (the coordinate limit) keep real runs far from this.
    representable[lane] = lane < n && RayEmbreeCanTake(rays[lane]);
    valid[lane] = representable[lane] ? -1 : 0;
    const Ray& ray = representable[lane] ? rays[lane] : kHarmlessRay;  // inactive lanes: any finite ray
    packet.ray.org_x[lane] = ray.origin_W.x();
    packet.ray.org_y[lane] = ray.origin_W.y();
    packet.ray.org_z[lane] = ray.origin_W.z();
    packet.ray.tnear[lane] = 0.0f;
    packet.ray.dir_x[lane] = ray.direction_W.x();
    packet.ray.dir_y[lane] = ray.direction_W.y();
    packet.ray.dir_z[lane] = ray.direction_W.z();
    packet.ray.time[lane] = 0.0f;
    packet.ray.tfar[lane] = ray.max_range_m;
    packet.ray.mask[lane] = 0xFFFFFFFFu;
    packet.ray.id[lane] = 0;
    packet.ray.flags[lane] = 0;
    packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);

  // the static world
  rtcIntersect8(valid, scenes.world, &context, &packet);
  for (std::size_t lane = 0; lane < n; ++lane)
    MapHit(packet, lane, scenes.direct_body, *scenes.world_bodies, bodies, &hits[lane]);

  // then the moving objects and the robot's links, each nearer than the
  // nearest hit so far (tfar holds it)
  const auto cast_instances = [&](RTCScene scene, const std::vector<int>& instance_bodies, bool Ray::*sees) {
    bool any = false;
    for (std::size_t lane = 0; lane < kPacketRays; ++lane) {
      valid[lane] = representable[lane] && rays[lane].*sees ? -1 : 0;
      any = any || valid[lane];
      packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    }
    if (!any) return;
    rtcIntersect8(valid, scene, &context, &packet);
    for (std::size_t lane = 0; lane < n; ++lane) {
      if (valid[lane] && packet.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
        MapHit(packet, lane, /*direct_body=*/-1, instance_bodies, bodies, &hits[lane]);
      }
    }
  };
  // the moving objects only when a ray may meet one of them (their scene is
  // then committed, if they moved since: ray_caster_internal.h)
  if (scenes.moving) {
    bool may_meet = !scenes.test_spheres;
    for (std::size_t lane = 0; lane < n && !may_meet; ++lane)
      may_meet = rays[lane].see_moving && MayMeetSphere(packet, lane, *scenes.moving_spheres_W);
    if (may_meet) {
      scenes.commit_moving();
      cast_instances(scenes.moving, *scenes.moving_bodies, &Ray::see_moving);
    }
  }
  // then each robot body the batch may meet, on its own (CastIntoRobotBody)
  if (!scenes.robot_candidates.empty()) {
    bool sees[kPacketRays];
    bool any = false;
    for (std::size_t lane = 0; lane < kPacketRays; ++lane) {
      sees[lane] = representable[lane] && rays[lane].see_robot;
      any = any || sees[lane];
    }
    if (any) {
      for (const int b : scenes.robot_candidates)
        CastIntoRobotBody(*bodies[static_cast<std::size_t>(b)], sees, context, packet, hits, n);
    }
  }
}

}  // namespace

void RayCaster::Cast(std::span<const Ray> rays, std::span<Hit> hits) const {
  assert(hits.size() == rays.size() && "one hit per ray");
  assert(impl_->committed && "Commit() after adding or moving bodies");
  const Impl& impl = *impl_;
  const auto packets = static_cast<std::ptrdiff_t>((rays.size() + kPacketRays - 1) / kPacketRays);
  const RobotCandidateList robot_candidates = impl.has_robot ? RobotCandidates(rays, impl.robot_bodies, impl.robot_spheres_W) : RobotCandidateList{};
  const CastScenes scenes{.world = impl.world_direct ? impl.world_direct : impl.scene_world,
                          .direct_body = impl.world_direct ? impl.world_direct_body : -1,
                          .robot_candidates = robot_candidates.bodies(),
                          .moving = impl.has_moving ? impl.scene_moving : nullptr,
                          .world_bodies = &impl.world_bodies,
                          .moving_bodies = &impl.moving_bodies,
                          .moving_spheres_W = &impl.moving_spheres_W,
                          .commit_moving = [impl = impl_.get()] { impl->CommitMovingIfMoved(); },
                          // committed already this sample (then cast as always), or too many rays to test
                          .test_spheres = impl.moving_uncommitted.load(std::memory_order_acquire) &&
                                          rays.size() * impl.moving_spheres_W.size() <= kMaxSphereTests};
  const auto cast_packet = [&](std::ptrdiff_t p) {
    const std::size_t first = static_cast<std::size_t>(p) * kPacketRays;
    CastPacket(scenes, impl.bodies, rays.data() + first, hits.data() + first, std::min(kPacketRays, rays.size() - first));
  };

  // every ray is independent, so the result does not depend on the thread count
  // (a batch is split on packet boundaries: the same packets either way)
  const std::size_t grain_packets = std::max<std::size_t>(1, kParallelBatchRays / kPacketRays);
  const auto cast_packets = [&](std::size_t begin, std::size_t end) {
    DenormalModeGuard denormal_mode;
    for (std::size_t p = begin; p < end; ++p) cast_packet(static_cast<std::ptrdiff_t>(p));
  };
  if (rays.size() >= kParallelBatchRays && impl.runner->threads() > 1) {
    impl.runner->For(static_cast<std::size_t>(packets), grain_packets, cast_packets);
  } else {
    cast_packets(0, static_cast<std::size_t>(packets));
  }
  impl_->ThrowIfDeviceError("Cast");
}

void RayCaster::set_threads(int threads) {
  assert(threads >= 1);
  if (threads != impl_->runner->threads()) impl_->runner = std::make_unique<ParallelRunner>(threads);
}

}  // namespace proxsim
