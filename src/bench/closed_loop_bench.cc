#include "bench/closed_loop_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>

#include "bench/bench_measures.h"
#include "bench/bench_process.h"
#include "run/run.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

}  // namespace

nlohmann::json ClosedLoopSection(const Scenario& heavy, const std::string& tmp, int repeats) {
  nlohmann::json section;

  // one world, many episodes: building the world against starting an episode on it
  double build_s = std::numeric_limits<double>::infinity();
  std::unique_ptr<Simulation> sim;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    sim = std::make_unique<Simulation>(heavy, 1);
    build_s = std::min(build_s, Since(start));
  }
  constexpr int kResets = 200;
  for (int k = 0; k < 50 && !sim->done(); ++k) sim->Step();  // an episode under way
  const auto start = Clock::now();
  for (int i = 0; i < kResets; ++i) sim->Reset(static_cast<std::uint64_t>(i));
  const double reset_s = Since(start) / kResets;
  section["build_heavy_world_s"] = build_s;
  section["reset_s"] = reset_s;
  section["reset_over_build"] = reset_s / build_s;
  std::fprintf(stderr, "closed loop: build the 1M-triangle world %.3f s, reset %.1f us (%.4f %% of the build)\n",
               build_s, reset_s * 1e6, 100 * reset_s / build_s);

  // the paper run in C++: its stepping loop with files written, and its steps alone
  double cpp_loop_s = std::numeric_limits<double>::infinity(), cpp_step_s = cpp_loop_s;
  for (int i = 0; i < repeats; ++i) {
    RunOptions options;
    options.out_dir = tmp + "/closed-loop-cpp";
    const RunResult run = RunScenario(LoadBuiltinScenario("paper"), options);
    (void)run;
    Simulation paper(LoadBuiltinScenario("paper"), 1);
    const auto step_start = Clock::now();
    while (!paper.done()) paper.Step();
    cpp_step_s = std::min(cpp_step_s, Since(step_start) / static_cast<double>(paper.sample_count()));
    // the loop's own wall time, as timings.json has it
    std::FILE* timings = std::fopen((options.out_dir + "/timings.json").c_str(), "r");
    if (timings != nullptr) {
      std::string text(4096, '\0');
      text.resize(std::fread(text.data(), 1, text.size(), timings));
      std::fclose(timings);
      cpp_loop_s = std::min(cpp_loop_s, nlohmann::json::parse(text)["loop_wall_s"].get<double>());
    }
  }
  section["cpp_paper_loop_wall_s"] = cpp_loop_s;
  section["cpp_step_s"] = cpp_step_s;

  // the same from Python, when the package was built
#ifdef PROXSIM_PYTHON_DIR
  const std::string command = "PYTHONPATH=" PROXSIM_PYTHON_DIR " /usr/bin/python3 " PROXSIM_SOURCE_DIR
                              "/bench/python_loop.py " + tmp + "/closed-loop-py --repeats " + std::to_string(repeats);
  const std::string output = Capture(command);
  const nlohmann::json python = nlohmann::json::parse(output, nullptr, false);
  if (!python.is_discarded() && python.contains("python_step_s")) {
    section["python_stop_rule_loop_wall_s"] = python["python_stop_rule_loop_wall_s"];
    section["python_over_cpp"] = python["python_stop_rule_loop_wall_s"].get<double>() / cpp_loop_s;
    section["binding_overhead_per_step_us"] = (python["python_step_s"].get<double>() - cpp_step_s) * 1e6;
    section["python_stop_requested_t_s"] = python["stop_requested_t_s"];
    // WalkEnv.step against what it cannot avoid: its two binding calls and its own Python work
    section["walk_env_step_s"] = python["walk_env_step_s"];
    section["walk_env_sim_step_s"] = python["walk_env_sim_step_s"];
    section["walk_env_python_s"] = python["walk_env_python_s"];
    section["walk_env_over_floor"] = python["walk_env_step_s"].get<double>() /
                                     (python["walk_env_sim_step_s"].get<double>() + python["walk_env_python_s"].get<double>());
    std::fprintf(stderr, "closed loop: WalkEnv.step %.1f us, sim.step + truth %.1f us, its own Python %.1f us (%.2fx)\n",
                 section["walk_env_step_s"].get<double>() * 1e6, section["walk_env_sim_step_s"].get<double>() * 1e6,
                 section["walk_env_python_s"].get<double>() * 1e6, section["walk_env_over_floor"].get<double>());
    std::fprintf(stderr,
                 "closed loop: paper run with the stop rule in Python %.3f s, in C++ %.3f s (%.2fx); binding "
                 "overhead %.1f us per step\n",
                 section["python_stop_rule_loop_wall_s"].get<double>(), cpp_loop_s,
                 section["python_over_cpp"].get<double>(), section["binding_overhead_per_step_us"].get<double>());
  } else {
    section["python_unavailable"] = "bench/python_loop.py gave no figures: " + output.substr(0, 200);
  }
#else
  section["python_unavailable"] = "the Python package was not built";
#endif
  std::filesystem::remove_all(tmp + "/closed-loop-cpp");
  std::filesystem::remove_all(tmp + "/closed-loop-py");
  return section;
}

std::string ClosedLoopReport(const nlohmann::json& s) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "\nclosed loop: building the 1M-triangle world %.3f s, Reset() %.1f us (%.4f %% of the build, "
                "target < 1 %%)\n",
                s.at("build_heavy_world_s").get<double>(), s.at("reset_s").get<double>() * 1e6,
                100 * s.at("reset_over_build").get<double>());
  std::string report = text;
  if (s.contains("python_over_cpp")) {
    std::snprintf(text, sizeof text,
                  "closed loop: paper run, stop rule in Python %.3f s vs C++ %.3f s: %.2fx (target <= 1.5x); binding "
                  "overhead %.1f us per step (C++ step %.1f us)\n",
                  s.at("python_stop_rule_loop_wall_s").get<double>(), s.at("cpp_paper_loop_wall_s").get<double>(),
                  s.at("python_over_cpp").get<double>(), s.at("binding_overhead_per_step_us").get<double>(),
                  s.at("cpp_step_s").get<double>() * 1e6);
    report += text;
    std::snprintf(text, sizeof text,
                  "closed loop: WalkEnv.step %.1f us (a new stride every step) vs sim.step + sim.truth %.1f us plus "
                  "its own Python %.1f us: %.2fx (target <= 1.5x)\n",
                  s.at("walk_env_step_s").get<double>() * 1e6, s.at("walk_env_sim_step_s").get<double>() * 1e6,
                  s.at("walk_env_python_s").get<double>() * 1e6, s.at("walk_env_over_floor").get<double>());
    report += text;
  } else {
    report += "closed loop: Python figures unavailable (" + s.value("python_unavailable", std::string("?")) + ")\n";
  }
  return report;
}

}  // namespace proxsim::bench
