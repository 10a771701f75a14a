// Bare Embree, the ceiling proxsim's pipeline is measured against: the bench
// scene's triangles in one flat scene (no instancing, no user geometry), and
// the rays handed over as single rays, packets or streams with nothing else
// done per ray.
#include <embree3/rtcore.h>
#include <omp.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <stdexcept>
#include <vector>

#include "bench/peers.h"
#include "raycast/embree_version.h"

namespace proxsim::bench {

const char* EmbreeCallName(EmbreeCall call) {
  switch (call) {
    case EmbreeCall::kSingle: return "rtcIntersect1";
    case EmbreeCall::kPacket4: return "rtcIntersect4";
    case EmbreeCall::kPacket8: return "rtcIntersect8";
    case EmbreeCall::kPacket16: return "rtcIntersect16";
    case EmbreeCall::kStream: return "rtcIntersect1M";
  }
  return "?";
}

std::string EmbreeVersion() { return RTC_VERSION_STRING; }

struct EmbreePeer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::atomic<long long> bytes{0};

  static bool OnMemory(void* user, ssize_t delta, bool /*post*/) {
    static_cast<Impl*>(user)->bytes.fetch_add(delta);
    return true;
  }
};

EmbreePeer::EmbreePeer(const BenchScene& scene, bool robust) : impl_(std::make_unique<Impl>()) {
  // bare Embree on the same code path as proxsim's own ray caster
  const std::string config = EmbreeDeviceConfig();
  impl_->device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
  if (!impl_->device) throw std::runtime_error("bench: cannot create an Embree device");
  rtcSetDeviceMemoryMonitorFunction(impl_->device, &Impl::OnMemory, impl_.get());
  const auto start = std::chrono::steady_clock::now();
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneFlags(impl_->scene, robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  for (const BenchObject& object : scene.objects) {
    const TriangleMesh& mesh = *object.mesh;
    RTCGeometry geometry = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh.vertices_O.size()));
    auto* t = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), mesh.triangles.size()));
    for (std::size_t i = 0; i < mesh.vertices_O.size(); ++i) {
      for (int k = 0; k < 3; ++k) v[3 * i + k] = mesh.vertices_O[i][k];
    }
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) t[3 * i + k] = mesh.triangles[i][k];
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(impl_->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(impl_->scene);
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (rtcGetDeviceError(impl_->device) != RTC_ERROR_NONE) throw std::runtime_error("bench: Embree build failed");
}

EmbreePeer::~EmbreePeer() {
  rtcReleaseScene(impl_->scene);
  rtcReleaseDevice(impl_->device);
}

std::size_t EmbreePeer::bytes() const { return static_cast<std::size_t>(std::max(0LL, impl_->bytes.load())); }

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

template <int N, typename RayHitN>
void CastPackets(RTCScene scene, std::span<const Ray> rays, std::span<float> distances, int threads,
                 void (*intersect)(const int*, RTCScene, RTCIntersectContext*, RayHitN*)) {
  const std::ptrdiff_t packets = static_cast<std::ptrdiff_t>((rays.size() + N - 1) / N);
#pragma omp parallel num_threads(threads)
  {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    alignas(64) RayHitN packet;
    alignas(64) int valid[N];
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
#pragma omp for schedule(static)
    for (std::ptrdiff_t p = 0; p < packets; ++p) {
      for (int k = 0; k < N; ++k) {
        const std::size_t i = static_cast<std::size_t>(p) * N + k;
        valid[k] = i < rays.size() ? -1 : 0;
        const Ray& ray = rays[i < rays.size() ? i : rays.size() - 1];
        packet.ray.org_x[k] = ray.origin_W.x();
        packet.ray.org_y[k] = ray.origin_W.y();
        packet.ray.org_z[k] = ray.origin_W.z();
        packet.ray.dir_x[k] = ray.direction_W.x();
        packet.ray.dir_y[k] = ray.direction_W.y();
        packet.ray.dir_z[k] = ray.direction_W.z();
        packet.ray.tnear[k] = 0.0f;
        packet.ray.tfar[k] = ray.max_range_m;
        packet.ray.time[k] = 0.0f;
        packet.ray.mask[k] = 0xFFFFFFFFu;
        packet.ray.id[k] = 0;
        packet.ray.flags[k] = 0;
        packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
      }
      intersect(valid, scene, &context, &packet);
      for (int k = 0; k < N; ++k) {
        const std::size_t i = static_cast<std::size_t>(p) * N + k;
        if (i < rays.size()) distances[i] = packet.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID ? kInf : packet.ray.tfar[k];
      }
    }
  }
}

void FillRayHit(const Ray& ray, RTCRayHit* rh) {
  rh->ray.org_x = ray.origin_W.x();
  rh->ray.org_y = ray.origin_W.y();
  rh->ray.org_z = ray.origin_W.z();
  rh->ray.dir_x = ray.direction_W.x();
  rh->ray.dir_y = ray.direction_W.y();
  rh->ray.dir_z = ray.direction_W.z();
  rh->ray.tnear = 0.0f;
  rh->ray.tfar = ray.max_range_m;
  rh->ray.time = 0.0f;
  rh->ray.mask = 0xFFFFFFFFu;
  rh->ray.id = 0;
  rh->ray.flags = 0;
  rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
}

}  // namespace

void EmbreePeer::Cast(std::span<const Ray> rays, std::span<float> distances, int threads) {
  RTCScene scene = impl_->scene;
  switch (call_) {
    case EmbreeCall::kSingle: {
      const auto n = static_cast<std::ptrdiff_t>(rays.size());
#pragma omp parallel num_threads(threads)
      {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
#pragma omp for schedule(static)
        for (std::ptrdiff_t i = 0; i < n; ++i) {
          RTCRayHit rh;
          FillRayHit(rays[i], &rh);
          rtcIntersect1(scene, &context, &rh);
          distances[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInf : rh.ray.tfar;
        }
      }
      break;
    }
    case EmbreeCall::kPacket4: CastPackets<4, RTCRayHit4>(scene, rays, distances, threads, &rtcIntersect4); break;
    case EmbreeCall::kPacket8: CastPackets<8, RTCRayHit8>(scene, rays, distances, threads, &rtcIntersect8); break;
    case EmbreeCall::kPacket16: CastPackets<16, RTCRayHit16>(scene, rays, distances, threads, &rtcIntersect16); break;
    case EmbreeCall::kStream: {
      constexpr std::size_t kBlock = 256;
      const auto blocks = static_cast<std::ptrdiff_t>((rays.size() + kBlock - 1) / kBlock);
#pragma omp parallel num_threads(threads)
      {
        _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
        _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
        std::vector<RTCRayHit> buffer(kBlock);
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
#pragma omp for schedule(static)
        for (std::ptrdiff_t b = 0; b < blocks; ++b) {
          const std::size_t first = static_cast<std::size_t>(b) * kBlock;
          const std::size_t m = std::min(kBlock, rays.size() - first);
          for (std::size_t k = 0; k < m; ++k) FillRayHit(rays[first + k], &buffer[k]);
          rtcIntersect1M(scene, &context, buffer.data(), static_cast<unsigned int>(m), sizeof(RTCRayHit));
          for (std::size_t k = 0; k < m; ++k) {
            distances[first + k] = buffer[k].hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInf : buffer[k].ray.tfar;
          }
        }
      }
      break;
    }
  }
}

}  // namespace proxsim::bench
