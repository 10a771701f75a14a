#include "bench/worlds_bench.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <sstream>

#include "bench/bench_measures.h"
#include "bench/step_timing.h"
#include "scenario/scenario.h"
#include "scenario/scenario_generate.h"
#include "scene/world_generator.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

constexpr int kMovingObjects = 50;

// The paper's walk without its stop rule or map, in the bench's room.
Scenario PaperLikeIn(const BenchScene& scene) {
  Scenario scenario = LoadBuiltinScenario("paper");
  scenario.robot->strategy.reset();
  scenario.map.enabled = false;
  scenario.builtin_scene = "bench_dining_room";
  scenario.scene = ToScene(scene);
  return scenario;
}

// 50 boxes of 0.2 m circling on loops of their own about the room, off the
// robot's way; or, not `moving`, standing where those loops start
void AddBoxes(Scenario& scenario, bool moving) {
  for (int i = 0; i < kMovingObjects; ++i) {
    SceneObject box;
    box.name = "mover_" + std::to_string(i + 1);
    box.shape = Box{Vec3(0.2, 0.2, 0.2)};
    Motion motion;
    const double x0 = 0.5 + 0.08 * i, y0 = (i % 2 ? 1.0 : -1.0) * (0.9 + 0.01 * i);
    motion.waypoints_m = {Vec2(x0, y0), Vec2(x0 + 0.6, y0), Vec2(x0 + 0.6, y0 + 0.3)};
    motion.speed_m_s = 0.5 + 0.01 * i;
    motion.X_MO.translation() = Vec3(0, 0, 0.1);
    box.X_WO = MotionPoseAt(motion, 0);
    if (moving) box.motion = motion;
    scenario.scene.objects.push_back(box);
  }
}

// The slowest of 20 seeds: generating alone, and the round trip through the scenario text.
nlohmann::json GenerationTimes(const std::string& generate) {
  double generate_s = 0, round_trip_s = 0;
  std::size_t objects = 0;
  for (int seed = 1; seed <= 20; ++seed) {
    const std::string text = "proxsim: 1\nscene:\n  generate: {" + generate + ", seed: " + std::to_string(seed) +
                             ", difficulty: 1}\nrobot: {}\nsensors:\n  - {name: s, type: ideal, link: left_tibia}\n";
    GenerateConfig config;
    config.seed = static_cast<std::uint64_t>(seed);
    config.difficulty = 1;
    config.kind = generate.find("room") != std::string::npos ? GenerateConfig::Kind::kRoom : GenerateConfig::Kind::kCourse;
    auto start = Clock::now();
    const GeneratedWorld world = GenerateWorld(config);
    generate_s = std::max(generate_s, Since(start));
    start = Clock::now();
    const Scenario scenario = LoadScenarioText(text, "bench:generate");
    round_trip_s = std::max(round_trip_s, Since(start));
    objects = std::max(objects, scenario.scene.objects.size());
    (void)world;
  }
  return {{"generate_max_ms", 1e3 * generate_s}, {"generate_and_read_max_ms", 1e3 * round_trip_s}, {"objects_max", objects}};
}

}  // namespace

nlohmann::json WorldsSection(bool quick, const BenchScene& scene_1m) {
  const BenchScene made = scene_1m.objects.empty() ? MakeBenchDiningRoom(1'000'000) : BenchScene{};
  const BenchScene& scene = scene_1m.objects.empty() ? made : scene_1m;
  // pairs of walks interleaved, in the thread's CPU time (bench/step_timing.h):
  // on a busy 2-core machine the best of a few wall-clock walks swung from −5 % to +55 %
  const int pairs = quick ? 3 : 15;
  const Scenario still = PaperLikeIn(scene);
  Scenario moving = still, standing = still;
  AddBoxes(moving, true);
  AddBoxes(standing, false);
  const StepComparison c = CompareSteps(still, moving, pairs);
  // the same 50 boxes standing: what their motion costs, apart from what their presence changes
  // (a robot nearer things caps its clearance queries nearer)
  const StepComparison m = CompareSteps(standing, moving, pairs);
  Progress("worlds: a paper-like sample in the %zu-triangle room %.1f µs CPU, with %d moving objects %.1f µs: "
           "%+.1f %% (median of %d interleaved pairs; quartiles %+.1f %% to %+.1f %%, all %+.1f %% to %+.1f %%; "
           "load %.1f → %.1f)",
           scene.triangle_count, 1e6 * c.base_s, kMovingObjects, 1e6 * c.other_s, 100 * c.extra_fraction, pairs,
           100 * c.extra_fraction_lo, 100 * c.extra_fraction_hi, 100 * c.extra_fraction_min,
           100 * c.extra_fraction_max, c.load_before, c.load_after);
  Progress("worlds: the same boxes standing %.1f µs, moving %.1f µs: %+.1f %% (quartiles %+.1f %% to %+.1f %%); "
           "least clearance still %.3f m, standing %.3f m, moving %.3f m",
           1e6 * m.base_s, 1e6 * m.other_s, 100 * m.extra_fraction, 100 * m.extra_fraction_lo,
           100 * m.extra_fraction_hi, c.base_min_clearance_m, m.base_min_clearance_m, c.other_min_clearance_m);
  nlohmann::json section = {{"triangles", scene.triangle_count},
                            {"moving_objects", kMovingObjects},
                            {"clock", "thread_cpu"},
                            {"pairs", pairs},
                            {"step_still_us", 1e6 * c.base_s},
                            {"step_moving_us", 1e6 * c.other_s},
                            {"step_still_wall_us", 1e6 * c.base_wall_s},
                            {"step_moving_wall_us", 1e6 * c.other_wall_s},
                            {"moving_extra_fraction", c.extra_fraction},
                            {"moving_extra_fraction_quartiles", {c.extra_fraction_lo, c.extra_fraction_hi}},
                            {"moving_extra_fraction_range", {c.extra_fraction_min, c.extra_fraction_max}},
                            {"load_average_1min", {c.load_before, c.load_after}},
                            {"min_clearance_still_m", c.base_min_clearance_m},
                            {"min_clearance_moving_m", c.other_min_clearance_m},
                            {"min_clearance_standing_m", m.base_min_clearance_m},
                            {"step_standing_us", 1e6 * m.base_s},
                            {"moving_vs_standing_fraction", m.extra_fraction},
                            {"moving_vs_standing_quartiles", {m.extra_fraction_lo, m.extra_fraction_hi}},
                            {"moving_target_fraction", 0.10}};
  section["course_20m"] = GenerationTimes("kind: course, length_m: 20");
  section["room_10x10m"] = GenerationTimes("kind: room, size_m: [10, 10]");
  section["generation_target_ms"] = 50;
  Progress("worlds: generating a 20 m course %.2f ms, a 10 x 10 m room %.2f ms (slowest of 20 seeds at difficulty 1)",
           section["course_20m"]["generate_max_ms"].get<double>(), section["room_10x10m"]["generate_max_ms"].get<double>());
  return section;
}

std::string WorldsReport(const nlohmann::json& s) {
  std::ostringstream out;
  char line[600];
  out << "\n## Worlds: moving objects and generated worlds\n\n";
  const auto pair = [&](const char* key, int i) { return 100 * s.at(key).at(i).get<double>(); };
  std::snprintf(line, sizeof line,
                "A paper-like sample in the %zu-triangle room: %.1f µs of CPU; with %d moving objects: %.1f µs, "
                "**%+.1f %%** (target ≤ %.0f %%; median of %d interleaved pairs of walks, quartiles %+.1f %% to "
                "%+.1f %%, load %.1f → %.1f).\n\n",
                s.at("triangles").get<std::size_t>(), s.at("step_still_us").get<double>(), s.at("moving_objects").get<int>(),
                s.at("step_moving_us").get<double>(), 100 * s.at("moving_extra_fraction").get<double>(),
                100 * s.at("moving_target_fraction").get<double>(), s.at("pairs").get<int>(),
                pair("moving_extra_fraction_quartiles", 0), pair("moving_extra_fraction_quartiles", 1),
                s.at("load_average_1min").at(0).get<double>(), s.at("load_average_1min").at(1).get<double>());
  out << line;
  std::snprintf(line, sizeof line,
                "The same 50 boxes standing where their loops start: %.1f µs; moving costs **%+.1f %%** over them "
                "(quartiles %+.1f %% to %+.1f %%). The robot's least clearance: %.3f m in the room alone, %.3f m "
                "with the boxes standing, %.3f m with them moving.\n\n",
                s.at("step_standing_us").get<double>(), 100 * s.at("moving_vs_standing_fraction").get<double>(),
                pair("moving_vs_standing_quartiles", 0), pair("moving_vs_standing_quartiles", 1),
                s.at("min_clearance_still_m").get<double>(), s.at("min_clearance_standing_m").get<double>(),
                s.at("min_clearance_moving_m").get<double>());
  out << line;
  out << "| world (difficulty 1, slowest of 20 seeds) | generate | generate + write + read | objects |\n|---|---|---|---|\n";
  for (const auto& [key, name] : {std::pair{"course_20m", "20 m course"}, {"room_10x10m", "10 × 10 m room"}}) {
    const auto& g = s.at(key);
    std::snprintf(line, sizeof line, "| %s | %.2f ms | %.2f ms | %zu |\n", name, g.at("generate_max_ms").get<double>(),
                  g.at("generate_and_read_max_ms").get<double>(), g.at("objects_max").get<std::size_t>());
    out << line;
  }
  std::snprintf(line, sizeof line, "\nTarget: under %d ms.\n", s.at("generation_target_ms").get<int>());
  out << line;
  return out.str();
}

}  // namespace proxsim::bench
