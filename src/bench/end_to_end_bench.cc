#include "bench/end_to_end_bench.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

#include "bench/bench_measures.h"
#include "bench/closed_loop_bench.h"
#include "bench/peers.h"
#include "run/run.h"
#include "sensors/beam.h"
#include "sensors/multizone.h"
#include "sim/make_locomotion.h"
#include "sim/robot_in_scene.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

using nlohmann::json;

json ReadJsonFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  return json::parse(in);
}

/// The default paper run, as `proxsim run --no-report` runs it, at 1 and 2 threads.
json PaperRun(const std::filesystem::path& tmp) {
  json paper_run;
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
    paper_run["wall_s_" + t] = wall_s;
    paper_run["simulated_s_per_wall_s_" + t] = paper.duration_s / wall_s;
    paper_run["loop_simulated_s_per_wall_s_" + t] = timings["simulated_s_per_wall_s"];
    Progress("paper run, %d thread%s: %.3f s wall for %.1f simulated s", threads, threads > 1 ? "s" : "", wall_s,
             paper.duration_s);
  }
  return paper_run;
}

/// The heavy scenario run with its outputs written (npy readings), at 1 and 2 threads; into `h`.
void HeavyRun(const Scenario& heavy, std::size_t rays_per_sample, double duration_s, const std::filesystem::path& tmp,
              json& h) {
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
}

/// The simulation's steps alone (Simulation::Step: robot moved, every beam
/// cast and read, the strategy and the clearance truth), without outputs; into `h`.
void HeavyStepsOnly(const Scenario& heavy, std::size_t rays_per_sample, double duration_s, json& h) {
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
}

/// The heavy scenario's rays of its first `samples` samples, placed from the
/// link poses as the simulation places them (untimed).
std::vector<Ray> HeavyOwnRays(const Scenario& heavy, int samples) {
  std::vector<Ray> own_rays;
  RayCaster caster;
  const auto locomotion = MakeLocomotion(*heavy.robot, heavy.rate_hz);
  RobotInScene robot(locomotion->model(), caster, 0);
  for (int k = 0; k < samples && k < heavy.SampleCount(); ++k) {
    robot.Place(locomotion->Advance(static_cast<double>(k) / heavy.rate_hz));
    for (const SensorConfig& sensor : heavy.sensors) {
      const Pose X_WS = robot.X_WL(robot.model().LinkIndex(sensor.link)) * sensor.X_LS;
      for (const BeamRay& beam_ray : MakeSensorRays(sensor.spec)) {
        Ray ray;
        ray.origin_W = X_WS.translation().cast<float>();
        ray.direction_W = BeamRayDir_W(X_WS, beam_ray).cast<float>();
        ray.max_range_m = static_cast<float>(sensor.spec.max_range_m);
        own_rays.push_back(ray);
      }
    }
  }
  return own_rays;
}

/// Bare Embree on the heavy scenario's own rays (world only: the robot's
/// links are not in Embree's scene), and the ratios against it; into `h`.
void EmbreeOnOwnRays(const BenchScene& scene_1m, const std::vector<Ray>& rays, int repeats, json& h) {
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

/// Simulation steps (no outputs) of the paper scenario, and of the same walk
/// with a VL53L5CX (8x8 zones of 4 rays, at its 15 Hz limit) on each shin
/// instead of the paper's four single-ray sensors; best of `repeats` runs,
/// one thread. The same with the zones read at every sample (100 Hz, beyond
/// the part's limit) shows the zones' own cost per read; the paper walk and
/// the 15 Hz one again without a terrain map (map: {enabled: false}) part the
/// sensor's own cost from the map's work on its zones' points.
json MultizoneSteps(int repeats) {
  const Scenario paper = LoadBuiltinScenario("paper");
  const Scenario zoned = ZonedPaperScenario(15.0), every_sample = ZonedPaperScenario(0.0);
  const auto without_map = [](Scenario scenario) {
    scenario.map.enabled = false;
    return scenario;
  };
  const auto per_sample_s = [&](const Scenario& scenario) {
    double best = std::numeric_limits<double>::infinity();
    for (int r = 0; r < repeats; ++r) {
      Simulation simulation(scenario, 1);
      const auto start = Clock::now();
      while (!simulation.done()) simulation.Step();
      best = std::min(best, Since(start) / static_cast<double>(scenario.SampleCount()));
    }
    return best;
  };
  const double paper_s = per_sample_s(paper), zoned_s = per_sample_s(zoned), every_s = per_sample_s(every_sample);
  const double paper_no_map_s = per_sample_s(without_map(paper)), zoned_no_map_s = per_sample_s(without_map(zoned));
  Progress("multizone: %.1f us per sample with a VL53L5CX (8x8, 4 rays/zone, 15 Hz) on each shin against %.1f us "
           "for the paper's sensors (%.2fx); read at every sample: %.1f us (%.2fx); without a terrain map in either "
           "walk: %.1f us against %.1f us (%.2fx)",
           zoned_s * 1e6, paper_s * 1e6, zoned_s / paper_s, every_s * 1e6, every_s / paper_s, zoned_no_map_s * 1e6,
           paper_no_map_s * 1e6, zoned_no_map_s / paper_no_map_s);
  return {{"what", "the paper walk (100 Hz, 5 s) with a VL53L5CX (8x8 zones, 4 rays each, 15 Hz) on each shin instead "
                   "of the paper's four single-ray sensors; simulation steps only, 1 thread, best of " +
                       std::to_string(repeats)},
          {"paper_s_per_sample", paper_s},
          {"multizone_15hz_s_per_sample", zoned_s},
          {"multizone_15hz_cost_vs_paper", zoned_s / paper_s},
          {"multizone_every_sample_s_per_sample", every_s},
          {"multizone_every_sample_cost_vs_paper", every_s / paper_s},
          {"paper_no_map_s_per_sample", paper_no_map_s},
          {"multizone_15hz_no_map_s_per_sample", zoned_no_map_s},
          {"multizone_15hz_no_map_cost_vs_paper_no_map", zoned_no_map_s / paper_no_map_s}};
}

}  // namespace

json EndToEndSection(bool quick, int repeats, const BenchScene& scene_1m) {
  json section;
  const std::filesystem::path tmp =
      std::filesystem::temp_directory_path() / ("proxsim-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(tmp);

  section["paper_run"] = PaperRun(tmp);
  section["paper_run_wall_s"] = section["paper_run"]["wall_s_1t"];
  section["multizone"] = MultizoneSteps(quick ? 1 : 3);

  // the heavy scenario: 64 mountings × 32 rays at 1 kHz in the 1M-triangle room, outputs written
  constexpr int kMounts = 64, kRaysPerMount = 32;
  const double duration_s = quick ? 0.1 : 1.0;
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
  HeavyRun(heavy, rays_per_sample, duration_s, tmp, h);
  HeavyStepsOnly(heavy, rays_per_sample, duration_s, h);
  EmbreeOnOwnRays(scene_1m, HeavyOwnRays(heavy, quick ? 20 : 100), repeats, h);
  section["heavy"] = h;
  section["heavy_realtime_factor_1t"] = h["realtime_factor_1t"];
  section["heavy_realtime_factor_2t"] = h["realtime_factor_2t"];
  section["heavy_ray_ratio_vs_embree_2t"] = h["ray_ratio_vs_embree_2t"];
  section["heavy_steps_only_realtime_factor_2t"] = h["steps_only_realtime_factor_2t"];
  section["heavy_steps_only_ratio_vs_embree_2t"] = h["steps_only_ratio_vs_embree_2t"];
  section["closed_loop"] = ClosedLoopSection(heavy, tmp.string(), quick ? 1 : 3);
  std::filesystem::remove_all(tmp);
  return section;
}

std::string EndToEndReport(const json& r) {
  char line[1024];
  const auto M = [](const json& v) { return v.is_number() ? v.get<double>() / 1e6 : std::nan(""); };
  const json& h = r.at("heavy");
  std::snprintf(line, sizeof line,
                "\npaper run: %.3f s wall (1 thread), %.3f s (2 threads)\n"
                "heavy: %zu rays/sample (64 beams of 32) at 1 kHz, %.2f simulated s: %.2fx real time at 1 thread, %.2fx at 2 "
                "(%.2f / %.2f M rays/s; bare Embree on its rays %.2f / %.2f M rays/s; peak RSS +%.0f MB)\n"
                "heavy, simulation steps only (no outputs): %.2fx real time at 1 thread, %.2fx at 2 (%.2f / %.2f M rays/s)\n"
                "multizone: a VL53L5CX (8x8 zones of 4 rays, 15 Hz) on each shin costs %.2fx a paper sample "
                "(%.2fx when read at every sample; %.2fx with no terrain map in either walk)\n"
                "bench wall time: %.0f s\n",
                r.at("paper_run").at("wall_s_1t").get<double>(), r.at("paper_run").at("wall_s_2t").get<double>(),
                h.at("rays_per_sample").get<std::size_t>(), h.at("duration_s").get<double>(), h.at("realtime_factor_1t").get<double>(),
                h.at("realtime_factor_2t").get<double>(), M(h.at("rays_per_s_1t")), M(h.at("rays_per_s_2t")),
                M(h.at("embree_best_rays_per_s_own_rays_1t")), M(h.at("embree_best_rays_per_s_own_rays_2t")),
                h.at("peak_rss_above_start_bytes_2t").get<double>() / 1e6,
                h.at("steps_only_realtime_factor_1t").get<double>(), h.at("steps_only_realtime_factor_2t").get<double>(),
                M(h.at("steps_only_rays_per_s_1t")), M(h.at("steps_only_rays_per_s_2t")),
                r.at("multizone").at("multizone_15hz_cost_vs_paper").get<double>(),
                r.at("multizone").at("multizone_every_sample_cost_vs_paper").get<double>(),
                // (a run saved before this figure existed draws it as nan)
                r.at("multizone").value("multizone_15hz_no_map_cost_vs_paper_no_map", std::nan("")),
                r.at("bench_wall_s").get<double>());
  return line;
}

}  // namespace proxsim::bench
