// The suite behind `proxsim bench`: the machine, then each section the
// options select, in a fixed order — the engines on the ray sets
// (rays_bench.h), a real robot (robot_bench.h), footstep planning
// (terrain_bench.h), placement studies (study_bench.h), closed-loop studies
// (outcome_bench.h), the terrain map
// (map_bench.h), co-simulation and batched environments from Python
// (python_envs_bench.h), and last the end-to-end runs (end_to_end_bench.h), which
// walk in the 1M-triangle room the ray sets were cast in. Rays/s is always
// rays cast / wall time of the cast (plus, for proxsim, the sensor model and
// noise of every ray).
#include "bench/bench_suite.h"

#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "bench/bench_measures.h"
#include "bench/bench_scene.h"
#include "bench/closed_loop_bench.h"
#include "bench/end_to_end_bench.h"
#include "bench/map_bench.h"
#include "bench/outcome_bench.h"
#include "bench/worlds_bench.h"
#include "bench/peers.h"
#include "bench/python_envs_bench.h"
#include "bench/rays_bench.h"
#include "bench/robot_bench.h"
#include "bench/study_bench.h"
#include "bench/terrain_bench.h"

namespace proxsim::bench {

namespace {

using nlohmann::json;

/// Placement studies in a scratch folder of their own, removed after.
json StudyInScratch(bool quick) {
  const auto study_tmp = std::filesystem::temp_directory_path() / ("proxsim-bench-study-" + std::to_string(::getpid()));
  json section = StudySection(quick, study_tmp.string());
  std::filesystem::remove_all(study_tmp);
  return section;
}

/// Closed-loop (outcome) studies in a scratch folder of their own, removed after.
json OutcomesInScratch(bool quick) {
  const auto tmp = std::filesystem::temp_directory_path() / ("proxsim-bench-outcomes-" + std::to_string(::getpid()));
  json section = OutcomesSection(quick, tmp.string());
  std::filesystem::remove_all(tmp);
  return section;
}

}  // namespace

json RunBench(const BenchOptions& options) {
  SetProgress(options.progress);
  const auto bench_start = Clock::now();
  const std::size_t rays_per_set = options.quick ? 200'000 : 1'000'000;
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
  result["rays_per_set"] = rays_per_set;

  // the end-to-end runs' room: the ray sets' largest scene, or made for them alone
  BenchScene scene_1m;
  if (options.rays) {
    result.update(RaysSection(options.quick, rays_per_set, repeats, &scene_1m));
  } else if (options.end_to_end) {
    scene_1m = MakeBenchDiningRoom(1'000'000);
  }
  if (options.robots) {
    result["robots"] = RobotsSection(options.quick);
    result["contacts"] = ContactsSection(options.quick);
  }
  if (options.terrain) result["terrain"] = TerrainSection(options.quick);
  if (options.study) result["study"] = StudyInScratch(options.quick);
  if (options.outcomes) result["outcomes"] = OutcomesInScratch(options.quick);
  if (options.map) result["terrain_map"] = MapSection(options.quick);
  if (options.python) result["python_envs"] = PythonEnvsSection(options.quick);
  if (options.worlds) result["worlds"] = WorldsSection(options.quick, scene_1m);
  if (options.end_to_end) {
    result.update(EndToEndSection(options.quick, repeats, scene_1m));
    result["machine"]["load_average_1min_at_end"] = LoadAverage();
  }
  result["bench_wall_s"] = Since(bench_start);
  return result;
}

std::string BenchReport(const json& r) {
  std::ostringstream out;
  out << "proxsim bench — " << r.at("machine").at("cpu").get<std::string>() << ", load " << r.at("machine").at("load_average_1min_at_start")
      << " → " << r.at("machine").at("load_average_1min_at_end") << ", " << r.at("rays_per_set") << " rays per set\n\n";
  out << RaysReport(r) << EndToEndReport(r);
  if (r.contains("closed_loop")) out << ClosedLoopReport(r.at("closed_loop"));
  if (r.contains("robots")) out << RobotsReport(r.at("robots"));
  if (r.contains("contacts")) out << ContactsReport(r.at("contacts"));
  if (r.contains("terrain")) out << TerrainReport(r.at("terrain"));
  if (r.contains("terrain_map")) out << MapReport(r.at("terrain_map"));
  if (r.contains("worlds")) out << WorldsReport(r.at("worlds"));
  if (r.contains("study")) out << StudyReport(r.at("study"));
  if (r.contains("outcomes")) out << OutcomesReport(r.at("outcomes"));
  if (r.contains("python_envs")) out << PythonEnvsReport(r.at("python_envs"));
  return out.str();
}

}  // namespace proxsim::bench
