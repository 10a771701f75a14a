// The benchmark's dining room: the layout of scene/builtin_scenes.cc (room
// x −1…5, y −2…2, walls 2.5 m high, table at (2, 1.3), two chairs, cupboard,
// obstacle at (2.5, 0)) with every surface a closed triangle mesh:
//   - boxes are tessellated into square-ish cells of edge `cell_m` on every face;
//   - the floor is 1 m tiles 5 cm thick, the walls 1 m panels (so that an engine
//     without a BVH over meshes, MuJoCo, can still cull whole objects);
//   - table legs are tessellated cylinders with capped ends;
//   - clutter: UV spheres of 528 triangles (r 3–10 cm) at hashed spots on the
//     floor off the corridor |y| < 0.5 m, and on the table top.
// `cell_m` is found by bisection so that the room holds ~70 % of the target.
#include "bench/bench_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace proxsim::bench {

namespace {

/// splitmix64: a well-mixed 64-bit hash of (seed, index).
std::uint64_t Hash(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + index + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// A uniform double in [0, 1) from (seed, index, lane).
double Uniform(std::uint64_t seed, std::uint64_t index, std::uint64_t lane) {
  return static_cast<double>(Hash(seed ^ (lane * 0xD1B54A32D192ED03ull), index) >> 11) * 0x1.0p-53;
}

int Cells(double length_m, double cell_m) { return std::max(1, static_cast<int>(std::ceil(length_m / cell_m - 1e-9))); }

class MeshBuilder {
 public:
  /// A grid of 2·nu·nv triangles over the parallelogram corner + [0,1]·u + [0,1]·v, facing u × v.
  void Quad(const Vec3& corner, const Vec3& u, const Vec3& v, int nu, int nv) {
    const auto base = static_cast<std::uint32_t>(mesh_.vertices_O.size());
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        mesh_.vertices_O.push_back((corner + u * (double(i) / nu) + v * (double(j) / nv)).cast<float>());
      }
    }
    const auto row = static_cast<std::uint32_t>(nu + 1);
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nu; ++i) {
        const std::uint32_t a = base + j * row + i, b = a + 1, c = a + row + 1, d = a + row;
        mesh_.triangles.push_back({a, b, c});
        mesh_.triangles.push_back({a, c, d});
      }
    }
  }

  /// An axis-aligned box from min to max, every face outward and tessellated.
  void Box(const Vec3& lo, const Vec3& hi, double cell_m) {
    const Vec3 s = hi - lo;
    const int nx = Cells(s.x(), cell_m), ny = Cells(s.y(), cell_m), nz = Cells(s.z(), cell_m);
    const Vec3 ex(s.x(), 0, 0), ey(0, s.y(), 0), ez(0, 0, s.z());
    Quad(lo, ey, ex, ny, nx);                 // −z (faces down: ey × ex = −z)
    Quad(lo + ez, ex, ey, nx, ny);            // +z
    Quad(lo, ex, ez, nx, nz);                 // −y (ex × ez = −y)
    Quad(lo + ey, ez, ex, nz, nx);            // +y
    Quad(lo, ez, ey, nz, ny);                 // −x (ez × ey = −x)
    Quad(lo + ex, ey, ez, ny, nz);            // +x
  }

  /// A vertical cylinder on z0 with capped ends.
  void Cylinder(double x, double y, double z0, double radius_m, double length_m, double cell_m) {
    const int slices = std::max(8, Cells(2 * std::numbers::pi * radius_m, cell_m));
    const int stacks = Cells(length_m, cell_m);
    const auto base = static_cast<std::uint32_t>(mesh_.vertices_O.size());
    for (int k = 0; k <= stacks; ++k) {
      for (int i = 0; i < slices; ++i) {
        const double a = 2 * std::numbers::pi * i / slices;
        mesh_.vertices_O.push_back(Vec3f(float(x + radius_m * std::cos(a)), float(y + radius_m * std::sin(a)),
                                         float(z0 + length_m * k / stacks)));
      }
    }
    const auto ring = [&](int k, int i) { return base + static_cast<std::uint32_t>(k * slices + (i % slices)); };
    for (int k = 0; k < stacks; ++k) {
      for (int i = 0; i < slices; ++i) {
        mesh_.triangles.push_back({ring(k, i), ring(k, i + 1), ring(k + 1, i + 1)});
        mesh_.triangles.push_back({ring(k, i), ring(k + 1, i + 1), ring(k + 1, i)});
      }
    }
    // caps: fans around their centres
    const auto bottom = static_cast<std::uint32_t>(mesh_.vertices_O.size());
    mesh_.vertices_O.push_back(Vec3f(float(x), float(y), float(z0)));
    mesh_.vertices_O.push_back(Vec3f(float(x), float(y), float(z0 + length_m)));
    for (int i = 0; i < slices; ++i) {
      mesh_.triangles.push_back({bottom, ring(0, i + 1), ring(0, i)});
      mesh_.triangles.push_back({bottom + 1, ring(stacks, i), ring(stacks, i + 1)});
    }
  }

  /// A UV sphere of `stacks` stacks and 2·stacks slices: 4·stacks·(stacks − 1) triangles.
  void Sphere(const Vec3& centre, double radius_m, int stacks) {
    const int slices = 2 * stacks;
    const auto base = static_cast<std::uint32_t>(mesh_.vertices_O.size());
    mesh_.vertices_O.push_back((centre + Vec3(0, 0, -radius_m)).cast<float>());  // south pole
    for (int k = 1; k < stacks; ++k) {
      const double polar = std::numbers::pi * k / stacks;
      for (int i = 0; i < slices; ++i) {
        const double a = 2 * std::numbers::pi * i / slices;
        mesh_.vertices_O.push_back((centre + radius_m * Vec3(std::sin(polar) * std::cos(a),
                                                             std::sin(polar) * std::sin(a), -std::cos(polar)))
                                       .cast<float>());
      }
    }
    const auto north = static_cast<std::uint32_t>(mesh_.vertices_O.size());
    mesh_.vertices_O.push_back((centre + Vec3(0, 0, radius_m)).cast<float>());
    const auto at = [&](int k, int i) { return base + 1 + static_cast<std::uint32_t>((k - 1) * slices + (i % slices)); };
    for (int i = 0; i < slices; ++i) mesh_.triangles.push_back({base, at(1, i + 1), at(1, i)});
    for (int k = 1; k < stacks - 1; ++k) {
      for (int i = 0; i < slices; ++i) {
        mesh_.triangles.push_back({at(k, i), at(k, i + 1), at(k + 1, i + 1)});
        mesh_.triangles.push_back({at(k, i), at(k + 1, i + 1), at(k + 1, i)});
      }
    }
    for (int i = 0; i < slices; ++i) mesh_.triangles.push_back({north, at(stacks - 1, i), at(stacks - 1, i + 1)});
  }

  BenchObject Take(std::string name) {
    BenchObject object{std::move(name), std::make_shared<const TriangleMesh>(std::move(mesh_))};
    mesh_ = TriangleMesh{};
    return object;
  }

 private:
  TriangleMesh mesh_;
};

constexpr int kBallStacks = 12;  // 528 triangles per ball

/// The room and its furniture at cell size cell_m.
std::vector<BenchObject> Room(double cell_m) {
  std::vector<BenchObject> objects;
  MeshBuilder b;
  const auto box = [&](const std::string& name, const Vec3& lo, const Vec3& hi) {
    b.Box(lo, hi, cell_m);
    objects.push_back(b.Take(name));
  };
  // floor: 1 m tiles, 5 cm thick, top face at z = 0, flagged as the ground
  for (int ix = 0; ix < 6; ++ix) {
    for (int iy = 0; iy < 4; ++iy) {
      box("floor_tile_" + std::to_string(ix) + "_" + std::to_string(iy), Vec3(-1 + ix, -2 + iy, -0.05),
          Vec3(-1 + ix + 1, -2 + iy + 1, 0));
      objects.back().ground = true;
    }
  }
  // walls: 0.1 m thick, 2.5 m high, inner faces at x = −1, 5 and y = ±2, in panels of at most 1 m
  constexpr double kT = 0.1, kH = 2.5;
  const auto wall = [&](const std::string& name, const Vec3& lo, const Vec3& hi, int axis) {
    const int panels = static_cast<int>(std::ceil((hi[axis] - lo[axis]) - 1e-9));
    for (int p = 0; p < panels; ++p) {
      Vec3 plo = lo, phi = hi;
      plo[axis] = lo[axis] + (hi[axis] - lo[axis]) * p / panels;
      phi[axis] = lo[axis] + (hi[axis] - lo[axis]) * (p + 1) / panels;
      box(name + "_" + std::to_string(p), plo, phi);
    }
  };
  wall("wall_west", Vec3(-1 - kT, -2 - kT, 0), Vec3(-1, 2 + kT, kH), 1);
  wall("wall_east", Vec3(5, -2 - kT, 0), Vec3(5 + kT, 2 + kT, kH), 1);
  wall("wall_south", Vec3(-1, -2 - kT, 0), Vec3(5, -2, kH), 0);
  wall("wall_north", Vec3(-1, 2, 0), Vec3(5, 2 + kT, kH), 0);
  // table: top 1.2 × 0.8 × 0.04 at z 0.71–0.75 over (2, 1.3); cylinder legs r 3 cm
  box("table_top", Vec3(1.4, 0.9, 0.71), Vec3(2.6, 1.7, 0.75));
  int leg = 1;
  for (double dx : {-0.54, 0.54}) {
    for (double dy : {-0.34, 0.34}) {
      b.Cylinder(2.0 + dx, 1.3 + dy, 0, 0.03, 0.71, cell_m);
      objects.push_back(b.Take("table_leg_" + std::to_string(leg++)));
    }
  }
  // chairs: seat 0.42 m square at z 0.43–0.47, legs 3 cm, a back 0.45 m high
  for (int c = 0; c < 2; ++c) {
    const double x = c == 0 ? 1.1 : 2.9, y = 1.3, back_dx = c == 0 ? -1 : 1;
    const std::string name = "chair_" + std::to_string(c + 1);
    box(name + "_seat", Vec3(x - 0.21, y - 0.21, 0.43), Vec3(x + 0.21, y + 0.21, 0.47));
    int l = 1;
    for (double dx : {-1.0, 1.0}) {
      for (double dy : {-1.0, 1.0}) {
        const double cx = x + dx * 0.195, cy = y + dy * 0.195;
        box(name + "_leg_" + std::to_string(l++), Vec3(cx - 0.015, cy - 0.015, 0), Vec3(cx + 0.015, cy + 0.015, 0.43));
      }
    }
    const double bx = x + back_dx * 0.195;
    box(name + "_back", Vec3(bx - 0.015, y - 0.21, 0.47), Vec3(bx + 0.015, y + 0.21, 0.92));
  }
  box("cupboard", Vec3(1.0, -2.0, 0), Vec3(2.0, -1.5, 1.8));
  box("obstacle", Vec3(2.4, -0.15, 0), Vec3(2.6, 0.15, 0.15));
  return objects;
}

std::size_t Triangles(const std::vector<BenchObject>& objects) {
  std::size_t n = 0;
  for (const BenchObject& o : objects) n += o.mesh->triangles.size();
  return n;
}

/// Origins uniform in the room (0.1 m from the walls), 0.05–0.6 m high.
Vec3 RayOrigin(std::uint64_t seed, std::uint64_t i) {
  return Vec3(-0.9 + 5.8 * Uniform(seed, i, 0), -1.9 + 3.8 * Uniform(seed, i, 1), 0.05 + 0.55 * Uniform(seed, i, 2));
}

}  // namespace

BenchScene MakeBenchDiningRoom(std::size_t target_triangles) {
  // the room at ~70 % of the target: its triangle count falls as the cell grows
  const double room_target = 0.7 * static_cast<double>(target_triangles);
  double lo = 0.002, hi = 3.0;
  for (int iteration = 0; iteration < 40; ++iteration) {
    const double mid = std::sqrt(lo * hi);
    (static_cast<double>(Triangles(Room(mid))) > room_target ? lo : hi) = mid;
    if (hi / lo < 1.01) break;
  }
  BenchScene scene;
  scene.cell_m = hi;
  scene.objects = Room(hi);

  // clutter balls for the rest: on the floor off the corridor, one in five on the table
  const std::size_t room = Triangles(scene.objects);
  const std::size_t per_ball = 4 * kBallStacks * (kBallStacks - 1);
  const std::size_t balls = target_triangles > room ? (target_triangles - room + per_ball / 2) / per_ball : 0;
  MeshBuilder b;
  constexpr std::uint64_t kSeed = 0xC1A77E5;
  for (std::size_t k = 0; k < balls; ++k) {
    const double r = 0.03 + 0.07 * Uniform(kSeed, k, 0);
    Vec3 c;
    if (k % 5 == 4) {
      c = Vec3(1.45 + r + (1.1 - 2 * r) * Uniform(kSeed, k, 1), 0.95 + r + (0.7 - 2 * r) * Uniform(kSeed, k, 2), 0.75 + r);
    } else {
      // y in [0.55, 1.95] on either side of the corridor
      const double side = Uniform(kSeed, k, 3) < 0.5 ? -1 : 1;
      c = Vec3(-0.95 + r + (5.9 - 2 * r) * Uniform(kSeed, k, 1), side * (0.55 + r + (1.4 - 2 * r) * Uniform(kSeed, k, 2)), r);
    }
    b.Sphere(c, r, kBallStacks);
    scene.objects.push_back(b.Take("clutter_" + std::to_string(k)));
  }
  for (const BenchObject& o : scene.objects) {
    scene.triangle_count += o.mesh->triangles.size();
    scene.vertex_count += o.mesh->vertices_O.size();
  }
  return scene;
}

Scene ToScene(const BenchScene& scene) {
  Scene out;
  out.objects.reserve(scene.objects.size());
  Material material;  // varnished wood everywhere
  material.albedo = 0.6;
  material.specular = 0.1;
  for (const BenchObject& o : scene.objects) {
    out.objects.push_back(
        SceneObject{o.name, Mesh{"bench:" + o.name, Vec3(1, 1, 1), o.mesh}, Pose::Identity(), material, o.ground});
  }
  return out;
}

std::vector<Ray> IncoherentRays(std::size_t count, std::uint64_t seed) {
  std::vector<Ray> rays(count);
  for (std::size_t i = 0; i < count; ++i) {
    // uniform on the hemisphere x > 0: cos θ = x uniform in [0, 1), azimuth around x uniform
    const double x = Uniform(seed, i, 3), phi = 2 * std::numbers::pi * Uniform(seed, i, 4);
    const double s = std::sqrt(std::max(0.0, 1 - x * x));
    rays[i].origin_W = RayOrigin(seed, i).cast<float>();
    rays[i].direction_W = Vec3(x, s * std::cos(phi), s * std::sin(phi)).normalized().cast<float>();
    rays[i].max_range_m = 2.0f;
    rays[i].see_robot = false;
  }
  return rays;
}

std::vector<Ray> FanRays(std::size_t count, std::size_t fan_rays, std::uint64_t seed) {
  std::vector<Ray> rays(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t fan = i / fan_rays, k = i % fan_rays;
    // the fan's heading within ±60° of +x and elevation in [−30°, +10°]; its rays over 60° of azimuth
    const double heading = (Uniform(seed, fan, 5) - 0.5) * 2 * std::numbers::pi / 3;
    const double elevation = (-30 + 40 * Uniform(seed, fan, 6)) * std::numbers::pi / 180;
    const double azimuth = heading + (fan_rays > 1 ? (double(k) / (fan_rays - 1) - 0.5) : 0.0) * std::numbers::pi / 3;
    rays[i].origin_W = RayOrigin(seed, fan).cast<float>();
    rays[i].direction_W = Vec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                               std::sin(elevation)).normalized().cast<float>();
    rays[i].max_range_m = 2.0f;
    rays[i].see_robot = false;
  }
  return rays;
}

Scenario HeavyScenario(const BenchScene& scene, int mounts, int rays_per_mount, double duration_s) {
  Scenario scenario;
  scenario.source = "bench:heavy";
  scenario.seed = 7;
  scenario.duration_s = duration_s;
  scenario.rate_hz = 1000;
  scenario.builtin_scene = "bench_dining_room";
  scenario.scene = ToScene(scene);
  RobotConfig robot;
  robot.waypoints_m = {Vec2(0, 0), Vec2(4.5, 0)};
  scenario.robot = robot;

  // mountings spread over both tibias, thighs and feet, looking forward and a little down
  static const std::array<const char*, 6> kLinks = {"left_tibia", "right_tibia", "left_thigh",
                                                     "right_thigh", "left_foot", "right_foot"};
  for (int m = 0; m < mounts; ++m) {
    const int per_link = (mounts + 5) / 6;
    const char* link = kLinks[m / per_link % kLinks.size()];
    const int slot = m % per_link;
    SensorConfig sensor;
    // appended, not `"m" + std::to_string(m)`: GCC 12 takes that for an
    // overlapping memcpy (a false -Wrestrict at -O3)
    sensor.name = "m";
    sensor.name += std::to_string(m);
    sensor.spec = SensorSpec::Preset(SensorType::kUltrasonic);
    // a beam of rays_per_mount rays in a 25° cone (sensor beams: the first echo that counts wins)
    BeamSpec beam;
    beam.aperture_deg = 25.0;
    beam.rays = rays_per_mount;
    sensor.spec.beam = beam;
    sensor.link = link;
    sensor.X_LS.translation() = Vec3(0.06, (slot % 2 ? 0.03 : -0.03), -0.05 - 0.3 * slot / std::max(1, per_link));
    sensor.X_LS.linear() = RotationFromRpy(Vec3(0, (5 + 2.0 * slot) * std::numbers::pi / 180, 0));
    sensor.see_robot = true;
    scenario.sensors.push_back(std::move(sensor));
  }
  return scenario;
}

Scenario ZonedPaperScenario(double rate_hz) {
  const Scenario paper = LoadBuiltinScenario("paper");
  Scenario zoned = paper;
  zoned.sensors.clear();
  for (const char* leg : {"left_tibia", "right_tibia"}) {
    SensorConfig sensor = paper.sensors.front();
    sensor.name = std::string("tof_") + leg;
    sensor.link = leg;
    sensor.spec = *SensorSpec::PartPreset("vl53l5cx");
    sensor.rate_hz = rate_hz;
    zoned.sensors.push_back(sensor);
  }
  // the stop rule's floor margin of data/scenarios/multizone_shins.yaml (5σ of
  // the part's floor noise): with the default 0.03 m the robot stops on the
  // floor's noise at 0.14 s, and the walk would be measured standing
  if (zoned.robot && zoned.robot->strategy && std::holds_alternative<StopConfig>(*zoned.robot->strategy)) {
    std::get<StopConfig>(*zoned.robot->strategy).min_height_m = 0.05;
  }
  return zoned;
}

}  // namespace proxsim::bench
