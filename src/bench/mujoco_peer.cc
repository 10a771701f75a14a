// MuJoCo's mj_ray as a peer: one static mesh geom per bench object (MuJoCo
// needs closed meshes: an open one gets no volume and a zero bounding radius,
// so rays never reach it), loaded from generated MJCF with the convex hulls
// off and collisions off. mj_ray has no range: a hit beyond the ray's range is
// a miss here. MuJoCo is the wheel's (cmake/mujoco.cmake). mj_ray only reads the model and the data, so threads share them.
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "bench/peers.h"

#include <mujoco/mujoco.h>
#include <unistd.h>

#include <chrono>

namespace proxsim::bench {

std::string MujocoVersion() { return mj_versionString(); }

namespace {

class MujocoPeer : public RayPeer {
 public:
  MujocoPeer(mjModel* model, double build_s) : model_(model), data_(mj_makeData(model)), build_s_(build_s) {
    mj_forward(model_, data_);  // geom poses in W
  }
  ~MujocoPeer() override {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }

  void Cast(std::span<const Ray> rays, std::span<float> distances, int threads) override {
    const auto n = static_cast<std::ptrdiff_t>(rays.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 16)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const Ray& ray = rays[i];
      const mjtNum pnt[3] = {ray.origin_W.x(), ray.origin_W.y(), ray.origin_W.z()};
      const mjtNum vec[3] = {ray.direction_W.x(), ray.direction_W.y(), ray.direction_W.z()};
      int geom = -1;
      const mjtNum d = mj_ray(model_, data_, pnt, vec, nullptr, 1, -1, &geom, nullptr);
      distances[i] = d >= 0 && d <= ray.max_range_m ? static_cast<float>(d) : std::numeric_limits<float>::infinity();
    }
  }

  double build_s() const override { return build_s_; }
  std::size_t bytes() const override { return static_cast<std::size_t>(model_->nbuffer) + data_->nbuffer; }

 private:
  mjModel* model_;
  mjData* data_;
  double build_s_;
};

}  // namespace

std::unique_ptr<RayPeer> MakeMujocoPeer(const BenchScene& scene, std::string* why) {
  const auto start = std::chrono::steady_clock::now();
  // the MJCF, with every mesh's vertices and faces inline
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("proxsim-bench-" + std::to_string(::getpid()) + ".xml");
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
      *why = "cannot write " + path.string();
      return nullptr;
    }
    // (MuJoCo 2.x: no convex hulls, which mj_ray does not use; 3.0 dropped the
    // attribute, its rays meet a mesh's own faces whatever its hull)
    std::fputs("<mujoco model=\"bench\">\n", f);
    if (mj_version() < 300) std::fputs("<compiler convexhull=\"false\"/>\n", f);
    std::fputs("<default><geom contype=\"0\" conaffinity=\"0\"/></default>\n<asset>\n", f);
    for (std::size_t m = 0; m < scene.objects.size(); ++m) {
      const TriangleMesh& mesh = *scene.objects[m].mesh;
      std::fprintf(f, "<mesh name=\"m%zu\" vertex=\"", m);
      for (const Vec3f& v : mesh.vertices_O) std::fprintf(f, "%.9g %.9g %.9g ", v.x(), v.y(), v.z());
      std::fputs("\" face=\"", f);
      for (const auto& t : mesh.triangles) std::fprintf(f, "%u %u %u ", t[0], t[1], t[2]);
      std::fputs("\"/>\n", f);
    }
    std::fputs("</asset>\n<worldbody>\n", f);
    for (std::size_t m = 0; m < scene.objects.size(); ++m) std::fprintf(f, "<geom type=\"mesh\" mesh=\"m%zu\"/>\n", m);
    std::fputs("</worldbody>\n</mujoco>\n", f);
    std::fclose(f);
  }
  char error[1000] = "";
  mjModel* model = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  std::filesystem::remove(path);
  if (!model) {
    *why = std::string("MuJoCo could not load the bench scene: ") + error;
    return nullptr;
  }
  const double build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::make_unique<MujocoPeer>(model, build_s);
}

}  // namespace proxsim::bench
