#include "bench/study_bench.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "bench/bench_measures.h"
#include "bench/bench_process.h"
#include "core/embedded_files.h"
#include "study/study_config.h"
#include "study/study_runner.h"

namespace proxsim::bench {

namespace {

namespace fs = std::filesystem;

// 100 mountings on the left tibia (4 types x 5 heights x 5 pitches) on the
// paper's walk and scene, `seeds` seeds: 100 x seeds runs in `seeds` jobs.
std::string PaperStudy(int seeds) {
  return "proxsim_study: 1\n"
         "base: paper_dining_room.yaml\n"
         "candidates:\n"
         "  axes:\n"
         "    type: [ideal, laser, ultrasonic, reflectance]\n"
         "    link: left_tibia\n"
         "    along_m: {from: -0.40, to: -0.20, step: 0.05}\n"
         "    forward_m: 0.06\n"
         "    pitch_deg: {from: 0, to: 40, step: 10}\n"
         "seeds: {from: 1, to: " + std::to_string(seeds) + "}\n"
         "hazards: [obstacle]\n";
}

std::string WriteSeedStudy(const fs::path& dir, const std::string& name, int seeds) {
  fs::create_directories(dir);
  std::ofstream(dir / "paper_dining_room.yaml")
      << EmbeddedFiles().at("data/scenarios/paper_dining_room.yaml");
  const fs::path path = dir / name;
  std::ofstream(path) << PaperStudy(seeds);
  return path.string();
}

}  // namespace

nlohmann::json StudySection(bool quick, const std::string& tmp) {
  nlohmann::json section;
  const fs::path dir = fs::path(tmp) / "study-bench";
  const std::string study_1000 = WriteSeedStudy(dir, "study_1000.yaml", 10);
  const std::string self = SelfExecutable();

  // runs per second on one core: one worker thread, in this process
  {
    const StudyConfig study = LoadStudyFile(study_1000);
    bool writer = false;
    const auto start = Clock::now();
    RunStudy(study, {.out_dir = (dir / "one-core").string(), .threads = 1, .progress = false}, &writer);
    const double wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    const double runs = static_cast<double>(study.candidates.size() * study.variants.size() * study.seeds.size());
    section["runs_per_s_per_core"] = runs / wall_s;
    section["one_core_runs"] = runs;
    section["one_core_wall_s"] = wall_s;
    section["one_core_job_s"] = wall_s / static_cast<double>(study.variants.size() * study.seeds.size());
    std::fprintf(stderr, "study: %.0f runs of the paper walk on one core in %.2f s: %.0f runs/s/core (a job, one walk "
                 "carrying 100 candidates, %.3f s)\n", runs, wall_s, runs / wall_s,
                 section["one_core_job_s"].get<double>());
  }

  // a 1000-run study through the CLI, every core
  const double cli_s =
      TimeCommand_s("'" + self + "' study '" + study_1000 + "' --no-report --out '" + (dir / "cli").string() + "'");
  section["study_1000_runs_wall_s"] = cli_s;
  std::fprintf(stderr, "study: 1000 runs through `proxsim study` on every core: %.2f s (target < 60 s)\n", cli_s);

  // 2 MPI ranks against 1, one worker thread per rank
  if (Capture("command -v mpirun").empty()) {
    section["mpi_unavailable"] = "mpirun not found (scripts/install-deps.sh installs openmpi-bin)";
  } else {
    const int seeds = quick ? 80 : 200;  // enough work (~5-12 s on one core) for mpirun's start-up not to count
    const std::string study = WriteSeedStudy(dir, "study_mpi.yaml", seeds);
    const auto mpirun = [&](int ranks) {
      return TimeCommand_s("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun --oversubscribe -np " +
                           std::to_string(ranks) + " '" + self + "' study '" + study + "' --no-report --threads 1 --out '" +
                           (dir / ("mpi" + std::to_string(ranks))).string() + "'");
    };
    const double one_s = mpirun(1), two_s = mpirun(2);
    section["mpi_runs"] = 100 * seeds;
    section["mpi_1_rank_wall_s"] = one_s;
    section["mpi_2_ranks_wall_s"] = two_s;
    section["mpi_2_over_1"] = one_s > 0 && two_s > 0 ? nlohmann::json(one_s / two_s) : nlohmann::json(nullptr);
    std::fprintf(stderr, "study: %d runs under mpirun, 1 rank %.2f s, 2 ranks %.2f s: %.2fx (target >= 1.85x)\n",
                 100 * seeds, one_s, two_s, one_s / two_s);
  }
  fs::remove_all(dir);
  return section;
}

std::string StudyReport(const nlohmann::json& s) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "\nstudy: %.0f runs/s per core on the paper walk (%.0f runs in %.2f s, one worker; a job, one walk "
                "carrying 100 candidates, %.3f s); a 1000-run study through `proxsim study` on every core %.2f s "
                "(target < 60 s)\n",
                s.at("runs_per_s_per_core").get<double>(), s.at("one_core_runs").get<double>(),
                s.at("one_core_wall_s").get<double>(), s.at("one_core_job_s").get<double>(),
                s.at("study_1000_runs_wall_s").get<double>());
  std::string report = text;
  if (s.contains("mpi_unavailable")) {
    report += "study: MPI figures unavailable (" + s.at("mpi_unavailable").get<std::string>() + ")\n";
  } else {
    std::snprintf(text, sizeof text,
                  "study: %d runs under mpirun, 1 rank %.2f s, 2 ranks %.2f s: %.2fx (target >= 1.85x)\n",
                  s.at("mpi_runs").get<int>(), s.at("mpi_1_rank_wall_s").get<double>(),
                  s.at("mpi_2_ranks_wall_s").get<double>(),
                  s.at("mpi_2_over_1").is_null() ? 0.0 : s.at("mpi_2_over_1").get<double>());
    report += text;
  }
  return report;
}

}  // namespace proxsim::bench
