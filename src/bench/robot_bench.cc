#include "bench/robot_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include "bench/bench_measures.h"
#include "bench/step_timing.h"
#include "scenario/scenario.h"
#include "raycast/ray_caster.h"
#include "robot/robot_model.h"
#include "sim/contacts.h"
#include "sim/robot_in_scene.h"
#include "sim/simulation.h"

namespace proxsim::bench {

namespace {

const std::filesystem::path kH1Scenario = std::filesystem::path(PROXSIM_SOURCE_DIR) / "data/scenarios/h1_dining_room.yaml";

// The paper run without its stop rule (every sample walks), its four sensors
// moved to `link` at `X_LS` when a robot other than the biped carries them.
Scenario PaperLike(const Scenario& base, const std::string& link, const Pose& X_LS) {
  Scenario scenario = base;
  const Scenario paper = LoadBuiltinScenario("paper");
  scenario.sensors = paper.sensors;
  for (SensorConfig& sensor : scenario.sensors) {
    sensor.link = link;
    sensor.X_LS = X_LS;
  }
  scenario.duration_s = paper.duration_s;
  scenario.rate_hz = paper.rate_hz;
  scenario.robot->strategy.reset();
  return scenario;
}

// What checking the robot's contacts costs per sample of `scenario`: the same
// poses as its own run, placed in a world of their own, each checked by a
// ContactFinder as the simulation checks them; against the whole step.
struct ContactCost {
  double step_s = 0, contacts_s = 0;
};
ContactCost ContactCostPerStep(const Scenario& scenario, int repeats) {
  ContactCost best{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (int i = 0; i < repeats; ++i) {
    Simulation sim(scenario, 1);
    World world(scenario, &sim.locomotion()->model(), 1);
    const std::vector<FootFrame> feet = sim.locomotion()->Feet();
    ContactFinder finder(*world.robot(), world.ground_caster(), world.ground_ids(), feet);
    double step_s = 0, contacts_s = 0, min_clearance_m = std::numeric_limits<double>::infinity();
    std::int64_t steps = 0;
    while (!sim.done()) {
      const auto start = Clock::now();
      sim.Step();
      step_s += Since(start);
      world.robot()->Place(*sim.robot_state());
      world.caster().Commit();
      // the clearance the simulation measures anyway (its summary's truth), untimed
      const double clearance_m = world.robot()->ClearanceTo(world.ground_ids(), min_clearance_m);
      const auto contacts_start = Clock::now();
      finder.Find(std::min(clearance_m, min_clearance_m));
      contacts_s += Since(contacts_start);
      min_clearance_m = std::min(min_clearance_m, clearance_m);
      ++steps;
    }
    best.step_s = std::min(best.step_s, step_s / static_cast<double>(steps));
    best.contacts_s = std::min(best.contacts_s, contacts_s / static_cast<double>(steps));
  }
  return best;
}

}  // namespace

nlohmann::json ContactsSection(bool quick) {
  nlohmann::json section;
  const int repeats = quick ? 2 : 5;
  const Scenario paper = LoadBuiltinScenario("paper");
  const auto record = [&](const std::string& key, const Scenario& scenario) {
    const ContactCost cost = ContactCostPerStep(scenario, repeats);
    section[key + "_step_s"] = cost.step_s;
    section[key + "_contacts_s"] = cost.contacts_s;
    section[key + "_contacts_share"] = cost.contacts_s / cost.step_s;
    std::fprintf(stderr, "contacts: %s, a paper-like sample %.1f us, its contact check %.1f us (%.1f %%)\n", key.c_str(),
                 1e6 * cost.step_s, 1e6 * cost.contacts_s, 100 * cost.contacts_s / cost.step_s);
  };
  record("biped", PaperLike(paper, "left_tibia", paper.sensors[0].X_LS));
  if (std::filesystem::is_regular_file(kH1Scenario)) {
    const Scenario h1 = LoadScenarioFile(kH1Scenario.string());
    record("h1", PaperLike(h1, "left_knee_link", PoseFromXyzRpy(Vec3(0.06, 0, -0.30), Vec3(0, DegToRad(15), 0))));
  }
  return section;
}

std::string ContactsReport(const nlohmann::json& s) {
  std::string report = "\ncontacts (sim/contacts.h) per paper-like sample (target: at most 10 % biped, 20 % H1):\n";
  for (const char* key : {"biped", "h1"}) {
    if (!s.contains(std::string(key) + "_step_s")) continue;
    char line[256];
    std::snprintf(line, sizeof line, "  %s: %.1f us of %.1f us (%.1f %%)\n", key,
                  1e6 * s.at(std::string(key) + "_contacts_s").get<double>(),
                  1e6 * s.at(std::string(key) + "_step_s").get<double>(),
                  100 * s.at(std::string(key) + "_contacts_share").get<double>());
    report += line;
  }
  return report;
}

nlohmann::json RobotsSection(bool quick) {
  nlohmann::json section;
  const int repeats = quick ? 2 : 5;
  // the Unitree H1's description is not in the repository: it is read from beside it
  section["h1_available"] = std::filesystem::is_regular_file(std::filesystem::path(PROXSIM_SOURCE_DIR) /
                                                             "../shared/robots/h1_description/urdf/h1.urdf");
  if (!section["h1_available"].get<bool>()) {
    std::fprintf(stderr, "robots: ../shared/robots/h1_description is absent; the robots' section is skipped\n");
    return section;
  }
  const Scenario h1 = LoadScenarioFile(kH1Scenario.string());
  const RobotConfig& config = *h1.robot;
  const UrdfOptions options{.geometry = config.geometry, .package_paths = config.package_paths};

  // loading: the URDF and every mesh (the first load reads the files from
  // the page cache at best; the best of the repeats is the parse itself)
  double first_load_s = 0, load_s = std::numeric_limits<double>::infinity();
  std::unique_ptr<RobotModel> model;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    model = std::make_unique<RobotModel>(RobotModel::FromFile(config.model, options));
    const double s = Since(start);
    if (i == 0) first_load_s = s;
    load_s = std::min(load_s, s);
  }
  // its bodies: one per link in the ray caster (BVHs built) and the surface samples
  double bodies_s = std::numeric_limits<double>::infinity();
  std::size_t samples = 0;
  for (int i = 0; i < repeats; ++i) {
    const auto start = Clock::now();
    RayCaster caster;
    RobotInScene robot(*model, caster, 0);
    caster.Commit();
    bodies_s = std::min(bodies_s, Since(start));
    samples = 0;
    for (int link = 0; link < model->link_count(); ++link) samples += robot.surface_points_L(link).size();
  }
  section["h1_links"] = model->link_count();
  section["h1_mesh_files"] = model->MeshFileCount();
  section["h1_triangles"] = model->MeshTriangleCount();
  section["h1_surface_samples"] = samples;
  section["h1_first_load_s"] = first_load_s;
  section["h1_load_s"] = load_s;
  section["h1_bodies_s"] = bodies_s;
  std::fprintf(stderr, "robots: H1 (%zu triangles in %zu files) loaded in %.3f s (first %.3f s), bodies built in %.3f s\n",
               model->MeshTriangleCount(), model->MeshFileCount(), load_s, first_load_s, bodies_s);

  // one paper-like sample: the built-in biped, the H1 (visual, then collision geometry)
  const Scenario biped = PaperLike(LoadBuiltinScenario("paper"), "left_tibia", LoadBuiltinScenario("paper").sensors[0].X_LS);
  const Pose X_shin = PoseFromXyzRpy(Vec3(0.06, 0, -0.30), Vec3(0, DegToRad(15), 0));
  const Scenario h1_visual = PaperLike(h1, "left_knee_link", X_shin);
  Scenario h1_collision = h1_visual;
  h1_collision.robot->geometry = LinkGeometryKind::kCollision;
  const double biped_s = SecondsPerStep(biped, repeats);
  const double visual_s = SecondsPerStep(h1_visual, repeats);
  const double collision_s = SecondsPerStep(h1_collision, repeats);
  section["biped_step_s"] = biped_s;
  section["h1_step_s"] = visual_s;
  section["h1_collision_step_s"] = collision_s;
  section["h1_over_biped"] = visual_s / biped_s;
  std::fprintf(stderr, "robots: one paper-like sample: biped %.1f us, H1 %.1f us (%.2fx), H1 collision geometry %.1f us\n",
               1e6 * biped_s, 1e6 * visual_s, visual_s / biped_s, 1e6 * collision_s);
  return section;
}

std::string RobotsReport(const nlohmann::json& s) {
  if (!s.value("h1_available", false)) return "\nRobots: ../shared/robots/h1_description absent, not measured.\n";
  char text[1024];
  std::snprintf(text, sizeof text,
                "\n| robot (triangles) | load URDF + meshes (first) | build bodies | clearance samples | one paper-like sample | / biped |\n"
                "|---|---|---|---|---|---|\n"
                "| built-in biped (primitives) | | | | %.1f us | 1 |\n"
                "| Unitree H1, visual (%zu in %zu files) | %.3f s (%.3f s) | %.3f s | %zu | %.1f us | %.2f |\n"
                "| Unitree H1, collision | | | | %.1f us | %.2f |\n",
                1e6 * s.at("biped_step_s").get<double>(), s.at("h1_triangles").get<std::size_t>(),
                s.at("h1_mesh_files").get<std::size_t>(), s.at("h1_load_s").get<double>(),
                s.at("h1_first_load_s").get<double>(), s.at("h1_bodies_s").get<double>(),
                s.at("h1_surface_samples").get<std::size_t>(), 1e6 * s.at("h1_step_s").get<double>(),
                s.at("h1_over_biped").get<double>(), 1e6 * s.at("h1_collision_step_s").get<double>(),
                s.at("h1_collision_step_s").get<double>() / s.at("biped_step_s").get<double>());
  return text;
}

}  // namespace proxsim::bench
