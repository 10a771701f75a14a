// The suite behind `proxsim bench`. Per scene size: build every engine on the
// same triangles, cast the same ray sets at 1 and 2 threads, compare the
// answers, then the end-to-end runs. Rays/s is always rays cast / wall time
// of the cast (plus, for proxsim, the sensor model and noise of every ray).
#include "bench/bench_suite.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_scene.h"
#include "bench/closed_loop_bench.h"
#include "bench/map_bench.h"
#include "bench/robot_bench.h"
#include "bench/study_bench.h"
#include "bench/terrain_bench.h"
#include "bench/peers.h"
#include "core/parallel.h"
#include "sensors/noise.h"
#include "sensors/sensor_model.h"
#include "robot/robot_model.h"
#include "sensors/beam.h"
#include "sim/make_locomotion.h"
#include "sim/robot_in_scene.h"
#include "run/run.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

double Since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool g_progress = true;
template <typename... Args>
void Progress(const char* format, Args... args) {
  if (!g_progress) return;
  std::fprintf(stderr, "bench: ");
  std::fprintf(stderr, format, args...);
  std::fputc('\n', stderr);
}

/// Resident set size now, in bytes (/proc/self/statm).
double RssBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

/// Peak RSS (VmHWM) in bytes; ResetPeak() starts a new peak from the current RSS.
double PeakRssBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) * 1024.0;
  }
  return 0;
}
void ResetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }

double LoadAverage() {
  double one = 0;
  std::ifstream("/proc/loadavg") >> one;
  return one;
}

std::string CpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown";
}

constexpr float kInf = std::numeric_limits<float>::infinity();

/// proxsim's pipeline as the simulation runs it: one batched Cast, then per
/// ray the echo and the sensor model (laser preset), with the keyed Gaussian
/// drawn only when the echo counts (Simulation::MeasureSensor does the same).
struct Pipeline {
  const RayCaster* caster = nullptr;
  SensorSpec spec = SensorSpec::Preset(SensorType::kLaser);
  std::vector<Hit> hits;
  std::vector<Reading> readings;

  std::unique_ptr<ParallelRunner> runner;

  void Run(std::span<const Ray> rays, int threads) {
    if (!runner || runner->threads() != threads) runner = std::make_unique<ParallelRunner>(threads);
    hits.resize(rays.size());
    readings.resize(rays.size());
    caster->Cast(rays, hits);
    runner->For(rays.size(), 4096, [&](std::size_t begin, std::size_t end) { Measure(rays, begin, end); });
  }

  void Measure(std::span<const Ray> rays, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Hit& hit = hits[i];
      Echo echo;
      if (hit.is_hit()) {
        echo.distance_m = hit.distance_m;
        const Ray& ray = rays[i];
        echo.incidence_deg = IncidenceDeg(ray.direction_W.x(), ray.direction_W.y(), ray.direction_W.z(),
                                          hit.normal_W.x(), hit.normal_W.y(), hit.normal_W.z());
      }
      // (seed, sensor = beam of 32 rays, sample 0, ray in beam), as the simulation keys it
      readings[i] = proxsim::Measure(spec, echo, [i](int) {
        return NoiseDraw{KeyedGaussian({7, static_cast<std::uint32_t>(i / 32), 0, static_cast<std::uint32_t>(i % 32)})};
      });
    }
  }
};

/// Timing of `cast(rays)` for `rays.size()` rays, in rays/s (best of `repeats`).
template <typename F>
double RaysPerSecond(std::size_t rays, int repeats, F&& cast) {
  double best = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    cast();
    best = std::max(best, static_cast<double>(rays) / Since(start));
  }
  return best;
}

/// Hit/miss mismatches, the largest distance difference where both hit, and
/// how many rays differ by more than 1 mm (a ray that slipped through an edge
/// to a surface behind, rather than float rounding).
json Agreement(std::span<const float> a, std::span<const float> b) {
  std::size_t mismatches = 0, both = 0, over_1mm = 0;
  double max_diff = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const bool ha = std::isfinite(a[i]), hb = std::isfinite(b[i]);
    if (ha != hb) {
      ++mismatches;
    } else if (ha) {
      ++both;
      const double diff = std::abs(a[i] - b[i]);
      max_diff = std::max(max_diff, diff);
      if (diff > 1e-3) ++over_1mm;
    }
  }
  return {{"rays", std::min(a.size(), b.size())}, {"both_hit", both}, {"hit_miss_mismatches", mismatches},
          {"max_distance_diff_m", max_diff}, {"distance_diff_over_1mm", over_1mm}};
}

std::string SizeLabel(std::size_t target) {
  return target >= 1000000 ? std::to_string(target / 1000000) + "m" : std::to_string(target / 1000) + "k";
}

/// The rays/s of every engine on one ray set, at 1 and 2 threads.
json RaceOnRays(const char* set_name, std::span<const Ray> rays, Pipeline& pipeline, RayCaster& caster,
                EmbreePeer& embree, RayPeer* bullet, std::size_t bullet_rays, RayPeer* mujoco,
                std::size_t mujoco_rays, int repeats, std::vector<float>* proxsim_distances,
                std::vector<float>* embree_distances, std::vector<float>* bullet_distances,
                std::vector<float>* mujoco_distances) {
  json out = {{"rays", rays.size()}};
  std::vector<float> distances(rays.size());
  bool identical = true;
  std::vector<Hit> hits_1t;
  std::vector<Reading> readings_1t;
  for (int threads : {1, 2}) {
    const std::string t = std::to_string(threads) + "t";
    caster.set_threads(threads);
    out["proxsim_rays_per_s_" + t] = RaysPerSecond(rays.size(), repeats, [&] { pipeline.Run(rays, threads); });
    // where the pipeline's time goes: RayCaster::Cast alone, and the model (echo, noise, Measure) alone
    {
      std::vector<Hit> hits(rays.size());
      out["proxsim_cast_only_rays_per_s_" + t] = RaysPerSecond(rays.size(), repeats, [&] { caster.Cast(rays, hits); });
    }
    // the same answers whatever the thread count
    if (threads == 1) {
      hits_1t = pipeline.hits;
      readings_1t = pipeline.readings;
    } else {
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const Hit& a = hits_1t[i];
        const Hit& b = pipeline.hits[i];
        const Reading& ra = readings_1t[i];
        const Reading& rb = pipeline.readings[i];
        if (std::memcmp(&a.distance_m, &b.distance_m, sizeof(float)) != 0 || a.object_id != b.object_id ||
            a.normal_W != b.normal_W || ra.status != rb.status ||
            std::memcmp(&ra.d_m, &rb.d_m, sizeof(double)) != 0) {
          identical = false;
        }
      }
    }
    Progress("  %s %zu rays, %d thread%s: proxsim %.2f M rays/s", set_name, rays.size(), threads,
             threads > 1 ? "s" : "", out["proxsim_rays_per_s_" + t].get<double>() / 1e6);

    // bare Embree, every way of calling it; the best is the ceiling
    double best = 0;
    std::string best_call;
    for (EmbreeCall call : {EmbreeCall::kSingle, EmbreeCall::kPacket4, EmbreeCall::kPacket8, EmbreeCall::kPacket16,
                            EmbreeCall::kStream}) {
      embree.set_call(call);
      const double rps = RaysPerSecond(rays.size(), repeats, [&] { embree.Cast(rays, distances, threads); });
      out["embree_rays_per_s_" + t][EmbreeCallName(call)] = rps;
      if (rps > best) {
        best = rps;
        best_call = EmbreeCallName(call);
      }
      if (call == EmbreeCall::kSingle && threads == 1 && embree_distances) *embree_distances = distances;
    }
    out["embree_best_rays_per_s_" + t] = best;
    out["embree_best_call_" + t] = best_call;
    Progress("  %s bare Embree best %.2f M rays/s (%s)", set_name, best / 1e6, best_call.c_str());

    // the slow peers on a fixed prefix of the same rays
    const auto time_slow_peer = [&](const char* key, const char* name, RayPeer* peer, std::size_t count,
                                    std::vector<float>* distances_1t) {
      if (!peer) return;
      std::vector<float> d(count);
      const auto subset = rays.first(count);
      const double rays_per_s = RaysPerSecond(count, 1, [&] { peer->Cast(subset, d, threads); });
      out[std::string(key) + "_rays_per_s_" + t] = rays_per_s;
      if (threads == 1 && distances_1t) *distances_1t = d;
      Progress("  %s %s %.4f M rays/s on %zu rays", set_name, name, rays_per_s / 1e6, count);
    };
    time_slow_peer("bullet", "Bullet", bullet, bullet_rays, bullet_distances);
    time_slow_peer("mujoco", "MuJoCo", mujoco, mujoco_rays, mujoco_distances);
  }
  out["proxsim_bit_identical_1t_2t"] = identical;
  if (proxsim_distances) {
    proxsim_distances->resize(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
      (*proxsim_distances)[i] = hits_1t[i].is_hit() ? hits_1t[i].distance_m : kInf;
    }
  }
  out["bullet_rays"] = bullet ? bullet_rays : 0;
  out["mujoco_rays"] = mujoco ? mujoco_rays : 0;
  return out;
}

json ReadJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  return json::parse(in);
}

}  // namespace

json RunBench(const BenchOptions& options) {
  g_progress = options.progress;
  const auto bench_start = Clock::now();
  const std::size_t ray_count = options.quick ? 200'000 : 1'000'000;
  // best of a few: the first pass over a ray set pays for cold caches and
  // first-touched buffers, which would favour whichever engine runs second
  const int repeats = options.quick ? 2 : 3;
  json result;
  result["machine"] = {{"cpu", CpuModel()},
                       {"hardware_threads", static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN))},
                       {"load_average_1min_at_start", LoadAverage()}};
  result["versions"] = {{"proxsim", PROXSIM_VERSION}, {"embree", EmbreeVersion()}, {"bullet", BulletVersion()},
                        {"mujoco", MujocoVersion()}};
  result["quick"] = options.quick;
  result["rays_per_set"] = ray_count;

  const auto incoherent = IncoherentRays(ray_count, 1);
  const auto fans = FanRays(ray_count, 32, 2);
  BenchScene scene_1m;

  for (std::size_t target : {std::size_t{10'000}, std::size_t{100'000}, std::size_t{1'000'000}}) {
    if (!options.rays) {
      if (options.end_to_end && target == 1'000'000) scene_1m = MakeBenchDiningRoom(target);
      continue;
    }
    const std::string label = SizeLabel(target);
    auto start = Clock::now();
    BenchScene scene = MakeBenchDiningRoom(target);
    json size = {{"triangles", scene.triangle_count},
                 {"objects", scene.objects.size()},
                 {"cell_m", scene.cell_m},
                 {"generate_s", Since(start)}};
    Progress("scene %s: %zu triangles in %zu objects (generated in %.2f s)", label.c_str(), scene.triangle_count,
             scene.objects.size(), size["generate_s"].get<double>());

    // proxsim: the scene's objects as one static world body, as Simulation builds it
    double rss = RssBytes();
    start = Clock::now();
    RayCaster caster;
    {
      std::vector<BodyShape> shapes;
      const Scene as_scene = ToScene(scene);
      for (std::size_t id = 0; id < as_scene.objects.size(); ++id) {
        shapes.push_back({as_scene.objects[id].shape, as_scene.objects[id].X_WO, static_cast<std::int32_t>(id)});
      }
      caster.AddBody(std::move(shapes), BodyKind::kWorld);
      caster.Commit();
    }
    size["proxsim_build_s"] = Since(start);
    size["proxsim_bytes_rss"] = RssBytes() - rss;

    rss = RssBytes();
    EmbreePeer embree(scene, /*robust=*/false);
    size["embree_build_s"] = embree.build_s();
    size["embree_bytes"] = embree.bytes();
    size["embree_bytes_rss"] = RssBytes() - rss;

    std::string why_bullet, why_mujoco;
    rss = RssBytes();
    auto bullet = MakeBulletPeer(scene, &why_bullet);
    size["bullet_bytes_rss"] = RssBytes() - rss;
    if (bullet) size["bullet_build_s"] = bullet->build_s();
    else size["bullet_unavailable"] = why_bullet;
    Progress("  built: proxsim %.3f s, Embree %.3f s (%.1f MB), Bullet %s s", size["proxsim_build_s"].get<double>(),
             embree.build_s(), embree.bytes() / 1e6, bullet ? std::to_string(bullet->build_s()).c_str() : "n/a");
    rss = RssBytes();
    auto mujoco = MakeMujocoPeer(scene, &why_mujoco);
    size["mujoco_bytes_rss"] = RssBytes() - rss;
    if (mujoco) {
      size["mujoco_build_s"] = mujoco->build_s();
      size["mujoco_bytes"] = mujoco->bytes();
      Progress("  built: MuJoCo %.2f s", mujoco->build_s());
    } else {
      size["mujoco_unavailable"] = why_mujoco;
      Progress("  MuJoCo unavailable: %s", why_mujoco.c_str());
    }

    // the slow peers get a fixed prefix of the rays, sized to take about a second
    const std::size_t bullet_rays = std::min(ray_count, target >= 1'000'000 ? std::size_t{200'000} : std::size_t{500'000});
    const std::size_t mujoco_rays = options.quick ? (target >= 1'000'000 ? 100 : target >= 100'000 ? 500 : 2000)
                                                  : (target >= 1'000'000 ? 300 : target >= 100'000 ? 2000 : 10000);
    Pipeline pipeline;
    pipeline.caster = &caster;
    std::vector<float> d_proxsim, d_embree, d_bullet, d_mujoco;
    size["incoherent"] = RaceOnRays("incoherent", incoherent, pipeline, caster, embree, bullet.get(), bullet_rays,
                                    mujoco.get(), mujoco_rays, repeats, &d_proxsim, &d_embree, &d_bullet, &d_mujoco);
    size["fans"] = RaceOnRays("fans", fans, pipeline, caster, embree, bullet.get(), bullet_rays, mujoco.get(),
                              mujoco_rays, repeats, nullptr, nullptr, nullptr, nullptr);

    // Embree with proxsim's scene flag (robust), to separate its cost from the pipeline's
    std::vector<float> d_embree_robust(incoherent.size());
    {
      EmbreePeer robust(scene, /*robust=*/true);
      for (int threads : {1, 2}) {
        size["embree_robust_rays_per_s_" + std::to_string(threads) + "t"] =
            RaysPerSecond(incoherent.size(), repeats, [&] { robust.Cast(incoherent, d_embree_robust, threads); });
      }
    }

    // the answers compared, ray by ray (incoherent set; proxsim at 1 thread as the reference)
    size["agreement"] = {{"embree", Agreement(d_proxsim, d_embree)},
                         {"embree_robust", Agreement(d_proxsim, d_embree_robust)}};
    if (bullet) size["agreement"]["bullet"] = Agreement(d_proxsim, d_bullet);
    if (mujoco) size["agreement"]["mujoco"] = Agreement(d_proxsim, d_mujoco);

    // the ratios the targets are stated in: proxsim's pipeline over each peer, incoherent rays
    const json& inc = size["incoherent"];
    for (const char* t : {"1t", "2t"}) {
      const double p = inc[std::string("proxsim_rays_per_s_") + t];
      size[std::string("ratio_vs_embree_") + t] = p / inc[std::string("embree_best_rays_per_s_") + t].get<double>();
      size[std::string("ratio_vs_embree_single_") + t] =
          p / inc[std::string("embree_rays_per_s_") + t]["rtcIntersect1"].get<double>();
      if (bullet) size[std::string("ratio_vs_bullet_") + t] = p / inc[std::string("bullet_rays_per_s_") + t].get<double>();
      if (mujoco) size[std::string("ratio_vs_mujoco_") + t] = p / inc[std::string("mujoco_rays_per_s_") + t].get<double>();
    }
    const json& fan = size["fans"];
    size["fans_ratio_vs_embree_2t"] = fan["proxsim_rays_per_s_2t"].get<double>() / fan["embree_best_rays_per_s_2t"].get<double>();
    size["thread_scaling"] = inc["proxsim_rays_per_s_2t"].get<double>() / inc["proxsim_rays_per_s_1t"].get<double>();
    result["scenes"][label] = size;
    if (target >= 1'000'000) scene_1m = std::move(scene);
  }

  // the headline figures (at 2 threads: the whole machine)
  if (options.rays) {
  const json& s = result["scenes"];
  result["ratio_vs_embree_10k"] = s["10k"]["ratio_vs_embree_2t"];
  result["ratio_vs_embree_100k"] = s["100k"]["ratio_vs_embree_2t"];
  result["ratio_vs_embree_1m"] = s["1m"]["ratio_vs_embree_2t"];
  result["ratio_vs_bullet_100k"] = s["100k"].value("ratio_vs_bullet_2t", json(nullptr));
  result["ratio_vs_mujoco_100k"] = s["100k"].value("ratio_vs_mujoco_2t", json(nullptr));
  result["thread_scaling"] = s["100k"]["thread_scaling"];
  result["thread_scaling_1m"] = s["1m"]["thread_scaling"];
  }
  if (options.robots) result["robots"] = RobotsSection(options.quick);
  if (options.terrain) result["terrain"] = TerrainSection(options.quick);
  if (options.study) {
    const auto study_tmp =
        std::filesystem::temp_directory_path() / ("proxsim-bench-study-" + std::to_string(::getpid()));
    result["study"] = StudySection(options.quick, study_tmp.string());
    std::filesystem::remove_all(study_tmp);
  }
  if (options.map) result["terrain_map"] = MapSection(options.quick);
  if (!options.end_to_end) {
    result["bench_wall_s"] = Since(bench_start);
    return result;
  }

  // ---- end to end ----
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path() / ("proxsim-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(tmp);

  // the default paper run, as `proxsim run --no-report` runs it
  for (int threads : {1, 2}) {
    const Scenario paper = LoadBuiltinScenario("paper");
    RunOptions run_options;
    run_options.out_dir = (tmp / ("paper-" + std::to_string(threads))).string();
    run_options.threads = threads;
    const auto start = Clock::now();
    const RunResult run = RunScenario(paper, run_options);
    const double wall_s = Since(start);
    const json timings = ReadJsonFile(std::filesystem::path(run_options.out_dir) / "timings.json");
    const std::string t = std::to_string(threads) + "t";
    result["paper_run"]["wall_s_" + t] = wall_s;
    result["paper_run"]["simulated_s_per_wall_s_" + t] =
        paper.duration_s / wall_s;
    result["paper_run"]["loop_simulated_s_per_wall_s_" + t] = timings["simulated_s_per_wall_s"];
    Progress("paper run, %d thread%s: %.3f s wall for %.1f simulated s", threads, threads > 1 ? "s" : "", wall_s,
             paper.duration_s);
  }
  result["paper_run_wall_s"] = result["paper_run"]["wall_s_1t"];

  // the heavy scenario: 64 mountings × 32 rays at 1 kHz in the 1M-triangle room, outputs written
  {
    constexpr int kMounts = 64, kRaysPerMount = 32;
    const double duration_s = options.quick ? 0.1 : 1.0;
    const Scenario heavy = HeavyScenario(scene_1m, kMounts, kRaysPerMount, duration_s);
    std::size_t rays_per_sample = 0;
    for (const SensorConfig& sensor : heavy.sensors) rays_per_sample += MakeBeamRays(sensor.spec.beam).size();
    json h = {{"what", "64 ultrasonic sensors with 32-ray beams (25 deg cone) on the biped's legs, 1 kHz, walking in "
                       "the 1M-triangle room; outputs written: readings as .npy columns, profile.ply, poses.csv, "
                       "summary.json, scene.json"},
              {"sensors", heavy.sensors.size()},
              {"rays_per_sample", rays_per_sample},
              {"duration_s", duration_s},
              {"triangles", scene_1m.triangle_count}};
    for (int threads : {1, 2}) {
      RunOptions run_options;
      run_options.out_dir = (tmp / ("heavy-" + std::to_string(threads))).string();
      run_options.threads = threads;
      run_options.format = ReadingsFormat::kNpy;
      ResetPeak();
      const double rss_before = RssBytes();
      const auto start = Clock::now();
      RunScenario(heavy, run_options);
      const double wall_s = Since(start);
      const json timings = ReadJsonFile(std::filesystem::path(run_options.out_dir) / "timings.json");
      const std::string t = std::to_string(threads) + "t";
      const double loop_wall_s = timings["loop_wall_s"];
      const double rays = static_cast<double>(rays_per_sample) * heavy.SampleCount();
      h["wall_s_" + t] = wall_s;
      h["loop_wall_s_" + t] = loop_wall_s;
      h["realtime_factor_" + t] = duration_s / loop_wall_s;
      h["realtime_factor_with_setup_" + t] = duration_s / wall_s;
      h["rays_per_s_" + t] = rays / loop_wall_s;
      h["peak_rss_above_start_bytes_" + t] = PeakRssBytes() - rss_before;
      Progress("heavy run, %d thread%s: %.2f s loop for %.2f simulated s (%.2fx real time, %.2f M rays/s)", threads,
               threads > 1 ? "s" : "", loop_wall_s, duration_s, duration_s / loop_wall_s, rays / loop_wall_s / 1e6);
      std::filesystem::remove_all(run_options.out_dir);
    }

    // the simulation's steps alone (Simulation::Step: robot moved, every beam
    // cast and read, the strategy and the clearance truth), without outputs
    for (int threads : {1, 2}) {
      Simulation simulation(heavy, threads);
      const auto start = Clock::now();
      while (!simulation.done()) simulation.Step();
      const double wall_s = Since(start);
      const std::string t = std::to_string(threads) + "t";
      const double rays = static_cast<double>(rays_per_sample) * heavy.SampleCount();
      h["steps_only_realtime_factor_" + t] = duration_s / wall_s;
      h["steps_only_rays_per_s_" + t] = rays / wall_s;
      Progress("heavy run, simulation steps only (no outputs), %d thread%s: %.2fx real time, %.2f M rays/s", threads,
               threads > 1 ? "s" : "", duration_s / wall_s, rays / wall_s / 1e6);
    }

    // its rays for bare Embree: the first samples', placed from the link poses
    // as the simulation places them (untimed)
    std::vector<Ray> own_rays;
    {
      RayCaster caster;
      const auto locomotion = MakeLocomotion(*heavy.robot);
      RobotInScene robot(locomotion->model(), caster, 0);
      const int own_samples = options.quick ? 20 : 100;
      for (int k = 0; k < own_samples && k < heavy.SampleCount(); ++k) {
        robot.Place(locomotion->Advance(static_cast<double>(k) / heavy.rate_hz));
        for (const SensorConfig& sensor : heavy.sensors) {
          const Pose X_WS = robot.X_WL(robot.model().LinkIndex(sensor.link)) * sensor.X_LS;
          for (const BeamRay& beam_ray : MakeBeamRays(sensor.spec.beam)) {
            Ray ray;
            ray.origin_W = X_WS.translation().cast<float>();
            ray.direction_W = (X_WS.linear() * beam_ray.dir_S).cast<float>();
            ray.max_range_m = static_cast<float>(sensor.spec.max_range_m);
            own_rays.push_back(ray);
          }
        }
      }
    }

    // its own rays (the first samples', world only: the robot's links are not in Embree's scene), for bare Embree
    {
      const std::vector<Ray>& rays = own_rays;
      EmbreePeer embree(scene_1m, false);
      std::vector<float> d(rays.size());
      for (int threads : {1, 2}) {
        double best = 0;
        for (EmbreeCall call : {EmbreeCall::kSingle, EmbreeCall::kPacket8, EmbreeCall::kStream}) {
          embree.set_call(call);
          best = std::max(best, RaysPerSecond(rays.size(), repeats, [&] { embree.Cast(rays, d, threads); }));
        }
        const std::string t = std::to_string(threads) + "t";
        h["embree_best_rays_per_s_own_rays_" + t] = best;
        h["ray_ratio_vs_embree_" + t] = h["rays_per_s_" + t].get<double>() / best;
        h["steps_only_ratio_vs_embree_" + t] = h["steps_only_rays_per_s_" + t].get<double>() / best;
      }
      h["embree_own_rays"] = rays.size();
    }
    result["heavy"] = h;
    result["heavy_realtime_factor_1t"] = h["realtime_factor_1t"];
    result["heavy_realtime_factor_2t"] = h["realtime_factor_2t"];
    result["heavy_ray_ratio_vs_embree_2t"] = h["ray_ratio_vs_embree_2t"];
    result["heavy_steps_only_realtime_factor_2t"] = h["steps_only_realtime_factor_2t"];
    result["heavy_steps_only_ratio_vs_embree_2t"] = h["steps_only_ratio_vs_embree_2t"];
    result["closed_loop"] = ClosedLoopSection(heavy, tmp.string(), options.quick ? 1 : 3);
  }
  std::filesystem::remove_all(tmp);

  result["machine"]["load_average_1min_at_end"] = LoadAverage();
  result["bench_wall_s"] = Since(bench_start);
  return result;
}

std::string BenchReport(const json& r) {
  std::ostringstream out;
  char line[512];
  const auto M = [](const json& v) { return v.is_number() ? v.get<double>() / 1e6 : std::nan(""); };
  out << "proxsim bench — " << r.at("machine").at("cpu").get<std::string>() << ", load " << r.at("machine").at("load_average_1min_at_start")
      << " → " << r.at("machine").at("load_average_1min_at_end") << ", " << r.at("rays_per_set") << " rays per set\n\n";
  out << "| scene | rays | threads | proxsim pipeline | bare Embree best (call) | Embree robust | Bullet | MuJoCo | "
         "proxsim/Embree | proxsim/Bullet | proxsim/MuJoCo |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string label : {"10k", "100k", "1m"}) {
    if (!r.at("scenes").contains(label)) continue;
    const json& s = r.at("scenes").at(label);
    for (const char* set : {"incoherent", "fans"}) {
      const json& x = s.at(set);
      for (const char* t : {"1t", "2t"}) {
        const std::string T = t;
        const double p = x.at("proxsim_rays_per_s_" + T);
        const double e = x.at("embree_best_rays_per_s_" + T);
        const double b = x.value("bullet_rays_per_s_" + T, std::nan(""));
        const double m = x.value("mujoco_rays_per_s_" + T, std::nan(""));
        const std::string robust =
            std::string(set) == "incoherent" ? std::to_string(M(s.at("embree_robust_rays_per_s_" + T))).substr(0, 5) : "";
        std::snprintf(line, sizeof line, "| %s (%zu tri) | %s | %c | %.2f M/s | %.2f M/s (%s) | %s | %.3f M/s | %.5f M/s | %.2f | %.1f | %.0f |\n",
                      label.c_str(), s.at("triangles").get<std::size_t>(), set, t[0], p / 1e6, e / 1e6,
                      x.at("embree_best_call_" + T).get<std::string>().c_str(), robust.c_str(), b / 1e6, m / 1e6, p / e,
                      p / b, p / m);
        out << line;
      }
    }
  }
  out << "\n| scene | build: proxsim | Embree | Bullet | MuJoCo (MJCF parse + compile) | Embree BVH bytes | proxsim RSS Δ | "
         "agreement vs Embree / Bullet / MuJoCo (mismatches of rays, max |Δd|) |\n|---|---|---|---|---|---|---|---|\n";
  for (const std::string label : {"10k", "100k", "1m"}) {
    if (!r.at("scenes").contains(label)) continue;
    const json& s = r.at("scenes").at(label);
    std::string agree;
    for (const char* peer : {"embree", "bullet", "mujoco"}) {
      if (!s.at("agreement").contains(peer)) continue;
      const json& a = s.at("agreement").at(peer);
      char buf[128];
      std::snprintf(buf, sizeof buf, "%s%zu/%zu, %.1e m", agree.empty() ? "" : "; ", a.at("hit_miss_mismatches").get<std::size_t>(),
                    a.at("rays").get<std::size_t>(), a.at("max_distance_diff_m").get<double>());
      agree += buf;
    }
    std::snprintf(line, sizeof line, "| %s | %.3f s | %.3f s | %.3f s | %.2f s | %.1f MB | %.1f MB | %s |\n", label.c_str(),
                  s.at("proxsim_build_s").get<double>(), s.at("embree_build_s").get<double>(), s.value("bullet_build_s", std::nan("")),
                  s.value("mujoco_build_s", std::nan("")), s.at("embree_bytes").get<double>() / 1e6,
                  s.at("proxsim_bytes_rss").get<double>() / 1e6, agree.c_str());
    out << line;
  }
  const json& h = r.at("heavy");
  std::snprintf(line, sizeof line,
                "\npaper run: %.3f s wall (1 thread), %.3f s (2 threads)\n"
                "heavy: %zu rays/sample (64 beams of 32) at 1 kHz, %.2f simulated s: %.2fx real time at 1 thread, %.2fx at 2 "
                "(%.2f / %.2f M rays/s; bare Embree on its rays %.2f / %.2f M rays/s; peak RSS +%.0f MB)\n"
                "heavy, simulation steps only (no outputs): %.2fx real time at 1 thread, %.2fx at 2 (%.2f / %.2f M rays/s)\n"
                "bench wall time: %.0f s\n",
                r.at("paper_run").at("wall_s_1t").get<double>(), r.at("paper_run").at("wall_s_2t").get<double>(),
                h.at("rays_per_sample").get<std::size_t>(), h.at("duration_s").get<double>(), h.at("realtime_factor_1t").get<double>(),
                h.at("realtime_factor_2t").get<double>(), M(h.at("rays_per_s_1t")), M(h.at("rays_per_s_2t")),
                M(h.at("embree_best_rays_per_s_own_rays_1t")), M(h.at("embree_best_rays_per_s_own_rays_2t")),
                h.at("peak_rss_above_start_bytes_2t").get<double>() / 1e6,
                h.at("steps_only_realtime_factor_1t").get<double>(), h.at("steps_only_realtime_factor_2t").get<double>(),
                M(h.at("steps_only_rays_per_s_1t")), M(h.at("steps_only_rays_per_s_2t")), r.at("bench_wall_s").get<double>());
  out << line;
  if (r.contains("closed_loop")) out << ClosedLoopReport(r.at("closed_loop"));
  if (r.contains("robots")) out << RobotsReport(r.at("robots"));
  if (r.contains("terrain")) out << TerrainReport(r.at("terrain"));
  if (r.contains("terrain_map")) out << MapReport(r.at("terrain_map"));
  if (r.contains("study")) out << StudyReport(r.at("study"));
  return out.str();
}

}  // namespace proxsim::bench
