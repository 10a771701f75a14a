#include "bench/outcome_bench.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <sys/resource.h>

#include "bench/bench_measures.h"
#include "bench/bench_process.h"
#include "sim/world.h"
#include "study/outcome_config.h"
#include "study/outcome_runner.h"

namespace proxsim::bench {

namespace {

namespace fs = std::filesystem;

// User + system CPU time of this process so far, s.
double ProcessCpu_s() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// the walker: the builtin biped at the paper's gait, 10 s at 50 Hz
constexpr const char* kBase =
    "proxsim: 1\nseed: 1\nduration_s: 10.0\nrate_hz: 50\nscene: {builtin: empty}\n"
    "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n";


// the study; `baselines` false: without the blind and oracle baselines
std::string WriteStudy(const fs::path& dir, const std::string& name, int rooms, bool baselines = true) {
  fs::create_directories(dir);
  std::ofstream(dir / "walker.yaml") << kBase;
  const fs::path path = dir / name;
  std::ofstream(path) << "proxsim_study: 1\nmode: outcomes\nbase: walker.yaml\n"
                      << "sets: [{name: eight_lasers, sensors: " << EightShinLasers() << "}]\n"
                      << "strategies: [{name: stop}]\n" << (baselines ? "" : "baselines: []\n")
                      << "worlds: {generate: {kind: room, difficulty: 0.5}, seeds: {from: 1, to: " << rooms << "}}\n";
  return path.string();
}

}  // namespace

std::string EightShinLasers() {
  std::string sensors;
  int n = 0;
  for (const char* link : {"left_tibia", "right_tibia"}) {
    for (const char* yaw_pitch : {"0, 8, 0", "0, 20, 0", "0, 8, 30", "0, 8, -30"}) {
      sensors += std::string(n == 0 ? "" : ", ") + "{name: l" + std::to_string(n) + ", type: laser, link: " + link +
                 ", pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [" + yaw_pitch + "]}}";
      ++n;
    }
  }
  return "[" + sensors + "]";
}

nlohmann::json OutcomesSection(bool quick, const std::string& tmp) {
  nlohmann::json section;
  const fs::path dir = fs::path(tmp) / "outcome-bench";
  const int rooms = quick ? 10 : 40;
  const std::string study_path = WriteStudy(dir, "rooms.yaml", rooms);
  const std::string self = SelfExecutable();

  // closed-loop runs per second on one core: one worker thread, in this process
  {
    const OutcomeStudyConfig study = LoadOutcomeStudyFile(study_path);
    bool writer = false;
    const double cpu_start_s = ProcessCpu_s();
    const std::int64_t worlds_before = World::BuiltCount();
    const auto start = Clock::now();
    const OutcomeResults results =
        RunOutcomeStudy(study, {.out_dir = (dir / "one-core").string(), .threads = 1, .progress = false}, &writer);
    const double wall_s = Since(start);
    // one world per room (its bodies and acceleration structures), every run on it
    const std::int64_t worlds = World::BuiltCount() - worlds_before;
    // the CPU the study took (one worker: one core's worth at most): on a
    // machine shared with other jobs the wall time also counts the time the
    // worker waited for a core, which runs per CPU second leave out
    const double cpu_s = ProcessCpu_s() - cpu_start_s;
    double simulated_s = 0, runs = 0;
    for (const OutcomeJob& job : results) {
      for (const OutcomeRun& run : job.runs) {
        simulated_s += run.outcome_t_s;
        ++runs;
      }
    }
    section["outcome_runs_per_s_per_core"] = runs / wall_s;
    section["outcome_runs"] = runs;
    section["outcome_worlds_built"] = worlds;
    section["outcome_wall_s"] = wall_s;
    section["outcome_mean_episode_s"] = simulated_s / runs;
    section["outcome_cpu_s"] = cpu_s;
    section["outcome_runs_per_cpu_s"] = runs / cpu_s;
    section["load_average_1min"] = LoadAverage();
    Progress("outcomes: %.0f closed-loop runs (8 lasers and the blind and oracle baselines, stop rule, 10 x 10 m rooms "
             "at difficulty 0.5, episodes of "
             "%.1f s on average) on one core in %.2f s: %.1f runs/s/core "
             "(target 200); %.1f runs per CPU second; %lld worlds built for them (one per room, one for the study's check)",
             runs, simulated_s / runs, wall_s, runs / wall_s, runs / cpu_s, static_cast<long long>(worlds));
  }

  // what the baselines cost: the same rooms with the set alone, per episode
  // (the oracle's 279 rays and perfect map against the set's 8 lasers)
  {
    const OutcomeStudyConfig alone = LoadOutcomeStudyFile(WriteStudy(dir, "alone.yaml", rooms, false));
    bool writer = false;
    const double cpu_start_s = ProcessCpu_s();
    const OutcomeResults results =
        RunOutcomeStudy(alone, {.out_dir = (dir / "alone").string(), .threads = 1, .progress = false}, &writer);
    const double cpu_s = ProcessCpu_s() - cpu_start_s;
    double runs = 0;
    for (const OutcomeJob& job : results) runs += static_cast<double>(job.runs.size());
    section["outcome_without_baselines_runs_per_cpu_s"] = runs / cpu_s;
    Progress("outcomes: the set alone (baselines: []): %.1f runs per CPU second; with blind and oracle %.1f",
             runs / cpu_s, section["outcome_runs_per_cpu_s"].get<double>());
  }
  // 2 MPI ranks against 1, one worker thread per rank
  if (Capture("command -v mpirun").empty()) {
    section["outcome_mpi_unavailable"] = "mpirun not found (scripts/install-deps.sh installs openmpi-bin)";
  } else {
    const auto mpirun = [&](int ranks) {
      return TimeCommand_s("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np " +
                           std::to_string(ranks) + " '" + self + "' study '" + study_path +
                           "' --no-report --threads 1 --out '" + (dir / ("mpi" + std::to_string(ranks))).string() + "'");
    };
    const double one_s = mpirun(1), two_s = mpirun(2);
    section["outcome_mpi_runs"] = rooms;
    section["outcome_mpi_1_rank_wall_s"] = one_s;
    section["outcome_mpi_2_ranks_wall_s"] = two_s;
    section["outcome_mpi_2_over_1"] = one_s > 0 && two_s > 0 ? nlohmann::json(one_s / two_s) : nlohmann::json(nullptr);
    Progress("outcomes: %d runs under mpirun, 1 rank %.2f s, 2 ranks %.2f s: %.2fx", rooms, one_s, two_s, one_s / two_s);
  }
  fs::remove_all(dir);
  return section;
}

std::string OutcomesReport(const nlohmann::json& s) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "\noutcomes: %.1f closed-loop runs/s per core on generated 10 x 10 m rooms (8 lasers with the blind and "
                "oracle baselines, the stop rule, %.0f runs in %.2f s, episodes of %.1f s on average; target 200); "
                "%.1f runs per CPU second (the set alone: %.1f); %lld worlds built for them (one per room, one for the "
                "study's check of its sets)\n",
                s.at("outcome_runs_per_s_per_core").get<double>(), s.at("outcome_runs").get<double>(),
                s.at("outcome_wall_s").get<double>(), s.at("outcome_mean_episode_s").get<double>(),
                s.value("outcome_runs_per_cpu_s", 0.0), s.value("outcome_without_baselines_runs_per_cpu_s", 0.0),
                static_cast<long long>(s.value("outcome_worlds_built", std::int64_t{-1})));
  std::string report = text;
  if (s.contains("outcome_mpi_unavailable")) {
    report += "outcomes: MPI figures unavailable (" + s.at("outcome_mpi_unavailable").get<std::string>() + ")\n";
  } else {
    std::snprintf(text, sizeof text, "outcomes: %d runs under mpirun, 1 rank %.2f s, 2 ranks %.2f s: %.2fx\n",
                  s.at("outcome_mpi_runs").get<int>(), s.at("outcome_mpi_1_rank_wall_s").get<double>(),
                  s.at("outcome_mpi_2_ranks_wall_s").get<double>(),
                  s.at("outcome_mpi_2_over_1").is_null() ? 0.0 : s.at("outcome_mpi_2_over_1").get<double>());
    report += text;
  }
  return report;
}

}  // namespace proxsim::bench
