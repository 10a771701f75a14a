// Bullet's ray test as a peer: every object's triangles in one
// btTriangleIndexVertexArray under one btBvhTriangleMeshShape (Bullet's
// quantized BVH, its fastest static mesh), and btCollisionWorld::rayTest with
// a ClosestRayResultCallback per ray. rayTest keeps scratch state in its
// broadphase, so each thread gets its own collision world; the shape and its
// BVH are shared (read-only while casting).
#include <limits>
#include <vector>

#include "bench/peers.h"

#ifdef PROXSIM_HAVE_BULLET
#include <btBulletCollisionCommon.h>

#include <chrono>
#include <omp.h>
#endif

namespace proxsim::bench {

#ifdef PROXSIM_HAVE_BULLET

std::string BulletVersion() { return PROXSIM_BULLET_VERSION; }

namespace {

class BulletPeer : public RayPeer {
 public:
  explicit BulletPeer(const BenchScene& scene) {
    const auto start = std::chrono::steady_clock::now();
    // Bullet reads the arrays in place: keep flat copies alive for its lifetime
    for (const BenchObject& object : scene.objects) {
      auto& v = vertices_.emplace_back();
      auto& t = indices_.emplace_back();
      for (const Vec3f& p : object.mesh->vertices_O) v.insert(v.end(), {p.x(), p.y(), p.z()});
      for (const auto& tri : object.mesh->triangles) t.insert(t.end(), {int(tri[0]), int(tri[1]), int(tri[2])});
      btIndexedMesh mesh;
      mesh.m_numTriangles = static_cast<int>(object.mesh->triangles.size());
      mesh.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(t.data());
      mesh.m_triangleIndexStride = 3 * sizeof(int);
      mesh.m_numVertices = static_cast<int>(object.mesh->vertices_O.size());
      mesh.m_vertexBase = reinterpret_cast<const unsigned char*>(v.data());
      mesh.m_vertexStride = 3 * sizeof(float);
      mesh.m_indexType = PHY_INTEGER;
      mesh.m_vertexType = PHY_FLOAT;
      arrays_.addIndexedMesh(mesh, PHY_INTEGER);
    }
    shape_ = std::make_unique<btBvhTriangleMeshShape>(&arrays_, /*useQuantizedAabbCompression=*/true,
                                                      /*buildBvh=*/true);
    build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  ~BulletPeer() override {
    for (auto& w : worlds_) w.world->removeCollisionObject(w.object.get());
  }

  void Cast(std::span<const Ray> rays, std::span<float> distances, int threads) override {
    while (static_cast<int>(worlds_.size()) < threads) AddWorld();
    const auto n = static_cast<std::ptrdiff_t>(rays.size());
#pragma omp parallel num_threads(threads)
    {
      btCollisionWorld& world = *worlds_[omp_get_thread_num()].world;
#pragma omp for schedule(static)
      for (std::ptrdiff_t i = 0; i < n; ++i) {
        const Ray& ray = rays[i];
        const btVector3 from(ray.origin_W.x(), ray.origin_W.y(), ray.origin_W.z());
        const Vec3f end = ray.origin_W + ray.max_range_m * ray.direction_W;
        const btVector3 to(end.x(), end.y(), end.z());
        btCollisionWorld::ClosestRayResultCallback callback(from, to);
        world.rayTest(from, to, callback);
        distances[i] = callback.hasHit() ? callback.m_closestHitFraction * ray.max_range_m
                                         : std::numeric_limits<float>::infinity();
      }
    }
  }

  double build_s() const override { return build_s_; }
  std::size_t bytes() const override { return 0; }

 private:
  struct World {
    std::unique_ptr<btDefaultCollisionConfiguration> configuration;
    std::unique_ptr<btCollisionDispatcher> dispatcher;
    std::unique_ptr<btDbvtBroadphase> broadphase;
    std::unique_ptr<btCollisionWorld> world;
    std::unique_ptr<btCollisionObject> object;
  };

  void AddWorld() {
    World w;
    w.configuration = std::make_unique<btDefaultCollisionConfiguration>();
    w.dispatcher = std::make_unique<btCollisionDispatcher>(w.configuration.get());
    w.broadphase = std::make_unique<btDbvtBroadphase>();
    w.world = std::make_unique<btCollisionWorld>(w.dispatcher.get(), w.broadphase.get(), w.configuration.get());
    w.object = std::make_unique<btCollisionObject>();
    w.object->setCollisionShape(shape_.get());
    w.world->addCollisionObject(w.object.get());
    w.world->updateAabbs();
    worlds_.push_back(std::move(w));
  }

  std::vector<std::vector<float>> vertices_;
  std::vector<std::vector<int>> indices_;
  btTriangleIndexVertexArray arrays_;
  std::unique_ptr<btBvhTriangleMeshShape> shape_;
  std::vector<World> worlds_;
  double build_s_ = 0;
};

}  // namespace

std::unique_ptr<RayPeer> MakeBulletPeer(const BenchScene& scene, std::string*) {
  return std::make_unique<BulletPeer>(scene);
}

#else

std::string BulletVersion() { return "unavailable"; }

std::unique_ptr<RayPeer> MakeBulletPeer(const BenchScene&, std::string* why) {
  *why = "Bullet was not found when proxsim was configured (apt-get install libbullet-dev)";
  return nullptr;
}

#endif

}  // namespace proxsim::bench
