#include "bench/python_envs_bench.h"

#include <cstdio>

#include "bench/bench_process.h"

namespace proxsim::bench {

nlohmann::json PythonEnvsSection(bool quick) {
  nlohmann::json section;
#ifdef PROXSIM_PYTHON_DIR
  const std::string command = "PYTHONPATH=" PROXSIM_PYTHON_DIR " /usr/bin/python3 " PROXSIM_SOURCE_DIR
                              "/bench/python_envs.py --num-envs 64 --threads 2" +
                              std::string(quick ? " --repeats 1 --steps 150" : " --repeats 3 --steps 600");
  const std::string output = Capture(command);
  const nlohmann::json python = nlohmann::json::parse(output, nullptr, false);
  if (python.is_discarded() || !python.contains("vec_steps_per_s")) {
    section["python_unavailable"] = "bench/python_envs.py gave no figures: " + output.substr(0, 200);
    return section;
  }
  section = python;
  const double own_s = python["own_gait_step_s"], external_s = python["external_step_s"];
  section["external_overhead_per_step_us"] = (external_s - own_s) * 1e6;
  section["external_by_name_overhead_per_step_us"] = (python["external_by_name_step_s"].get<double>() - own_s) * 1e6;
  section["vec_over_walk_envs"] = python["vec_steps_per_s"].get<double>() / python["walk_env_steps_per_s"].get<double>();
  section["vec_threads_gain"] = python["vec_steps_per_s"].get<double>() / python["vec_1_thread_steps_per_s"].get<double>();
  section["vec_python_overhead_fraction"] =
      python["vec_python_overhead_s"].get<double>() / python["vec_cpp_step_s"].get<double>();
  std::fprintf(stderr, "python envs: external step %.1f us vs own gait %.1f us (%+.1f us); VecWalkEnv %.0f steps/s vs "
               "64 WalkEnvs %.0f (%.2fx), Python overhead %.2f %% of the C++ work\n",
               external_s * 1e6, own_s * 1e6, section["external_overhead_per_step_us"].get<double>(),
               section["vec_steps_per_s"].get<double>(), section["walk_env_steps_per_s"].get<double>(),
               section["vec_over_walk_envs"].get<double>(), 100 * section["vec_python_overhead_fraction"].get<double>());
#else
  (void)quick;
  section["python_unavailable"] = "the Python package was not built";
#endif
  return section;
}

std::string PythonEnvsReport(const nlohmann::json& s) {
  if (!s.contains("vec_steps_per_s")) {
    return "\npython envs: unavailable (" + s.value("python_unavailable", std::string("?")) + ")\n";
  }
  char text[1024];
  std::string report;
  std::snprintf(text, sizeof text,
                "\nco-simulation (paper run): sim.step(q=array, X_WP=(xyz, quat)) %.1f us, with q by name %.1f us, vs "
                "the own-gait sim.step() %.1f us: %+.1f us per step for setting the state from Python\n",
                s.at("external_step_s").get<double>() * 1e6, s.at("external_by_name_step_s").get<double>() * 1e6,
                s.at("own_gait_step_s").get<double>() * 1e6, s.at("external_overhead_per_step_us").get<double>());
  report += text;
  std::snprintf(text, sizeof text,
                "VecWalkEnv (paper, N = %d, %d threads): %.0f env steps/s vs %d separate WalkEnvs %.0f: %.2fx (target "
                ">= 1.8x); on 1 thread %.0f (threads' gain %.2fx); Python overhead per batched step %.1f us = %.2f %% "
                "of its C++ work %.2f ms (target < 10 %%); load average %.2f -> %.2f\n",
                s.at("num_envs").get<int>(), s.at("threads").get<int>(), s.at("vec_steps_per_s").get<double>(),
                s.at("num_envs").get<int>(), s.at("walk_env_steps_per_s").get<double>(),
                s.at("vec_over_walk_envs").get<double>(), s.at("vec_1_thread_steps_per_s").get<double>(),
                s.at("vec_threads_gain").get<double>(), s.at("vec_python_overhead_s").get<double>() * 1e6,
                100 * s.at("vec_python_overhead_fraction").get<double>(), s.at("vec_cpp_step_s").get<double>() * 1e3,
                s.at("load_average_1min_before").get<double>(), s.at("load_average_1min_after").get<double>());
  report += text;
  return report;
}

}  // namespace proxsim::bench
