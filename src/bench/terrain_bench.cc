#include "bench/terrain_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <vector>

#include "bench/bench_measures.h"
#include "gait/gait_walker.h"
#include "sim/make_locomotion.h"
#include "scenario/scenario.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

const std::filesystem::path kStairsScenario =
    std::filesystem::path(PROXSIM_SOURCE_DIR) / "data/scenarios/stairs_walk.yaml";

struct Planning {
  double per_sample_s = 0;  // the planning, spread over every sample
  double per_step_s = 0;    // per heel strike
  double evaluate_s = 0;    // the median call that plans nothing
  int steps = 0;
  long samples = 0;
};

// One walk of `scenario`'s robot over its world's terrain, every Advance() timed.
Planning TimePlanning(const Scenario& scenario, const TerrainQuery& terrain) {
  auto locomotion = MakeLocomotion(*scenario.robot, scenario.rate_hz);
  auto* walker = dynamic_cast<GaitWalker*>(locomotion.get());
  if (walker == nullptr) return {};
  walker->SetTerrain(&terrain);
  const long samples = static_cast<long>(scenario.duration_s * scenario.rate_hz);
  std::vector<double> plain_s, striking_s;
  Vec3 heel = walker->current_step().p_W_heel;
  for (long k = 0; k < samples; ++k) {
    const auto start = Clock::now();
    walker->Advance(k / scenario.rate_hz);
    const double call_s = Since(start);
    // a new step planned: its heel strike was crossed in this call
    const bool planned = walker->current_step().p_W_heel != heel;
    heel = walker->current_step().p_W_heel;
    (planned ? striking_s : plain_s).push_back(call_s);
  }
  Planning p;
  if (plain_s.empty()) return p;
  std::nth_element(plain_s.begin(), plain_s.begin() + plain_s.size() / 2, plain_s.end());
  p.evaluate_s = plain_s[plain_s.size() / 2];
  double total_s = 0;
  for (const double s : striking_s) total_s += std::max(0.0, s - p.evaluate_s);
  p.steps = static_cast<int>(striking_s.size());
  p.samples = samples;
  p.per_step_s = p.steps > 0 ? total_s / p.steps : 0;
  p.per_sample_s = total_s / static_cast<double>(samples);
  return p;
}

// Wall time per Simulation::Step of the paper run without its stop rule, best of `repeats`.
double PaperLikeStep_s(int repeats) {
  Scenario paper = LoadBuiltinScenario("paper");
  paper.robot->strategy.reset();
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < repeats; ++i) {
    Simulation sim(paper, 1);
    const auto start = Clock::now();
    while (!sim.done()) sim.Step();
    best = std::min(best, Since(start) / static_cast<double>(sim.sample_count()));
  }
  return best;
}

}  // namespace

nlohmann::json TerrainSection(bool quick) {
  const int repeats = quick ? 2 : 5;
  const Scenario stairs = LoadScenarioFile(kStairsScenario.string());
  // the world as the simulation builds it: its ray caster answers the terrain
  const Simulation world_of(stairs, 1);
  Planning best;
  best.per_sample_s = std::numeric_limits<double>::infinity();
  for (int i = 0; i < repeats; ++i) {
    const Planning p = TimePlanning(stairs, world_of.world().terrain());
    if (p.per_sample_s < best.per_sample_s) best = p;
  }
  const double paper_step_s = PaperLikeStep_s(repeats);
  nlohmann::json section;
  section["stairs_steps_planned"] = best.steps;
  section["stairs_samples"] = best.samples;
  section["planning_per_step_us"] = best.per_step_s * 1e6;
  section["planning_per_sample_us"] = best.per_sample_s * 1e6;
  section["gait_evaluate_per_sample_us"] = best.evaluate_s * 1e6;
  section["paper_like_sample_us"] = paper_step_s * 1e6;
  section["planning_over_paper_sample"] = best.per_sample_s / paper_step_s;
  std::fprintf(stderr,
               "terrain: planning a footstep on the stairs course %.1f us (%d steps over %ld samples: %.3f us per "
               "sample), %.2f %% of a paper-like sample (%.1f us; target < 5 %%)\n",
               best.per_step_s * 1e6, best.steps, best.samples, best.per_sample_s * 1e6,
               100 * best.per_sample_s / paper_step_s, paper_step_s * 1e6);
  return section;
}

std::string TerrainReport(const nlohmann::json& s) {
  char text[512];
  std::snprintf(text, sizeof text,
                "\nterrain: planning a footstep on the stairs course %.1f us per step (%d steps), %.3f us per sample "
                "at %ld samples: %.2f %% of a paper-like sample's %.1f us (target < 5 %%); evaluating the planned "
                "step %.2f us per sample\n",
                s.at("planning_per_step_us").get<double>(), s.at("stairs_steps_planned").get<int>(),
                s.at("planning_per_sample_us").get<double>(), s.at("stairs_samples").get<long>(),
                100 * s.at("planning_over_paper_sample").get<double>(), s.at("paper_like_sample_us").get<double>(),
                s.at("gait_evaluate_per_sample_us").get<double>());
  return text;
}

}  // namespace proxsim::bench
