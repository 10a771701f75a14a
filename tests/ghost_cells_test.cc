// The map forgets what moved (docs/terrain_map.md, docs/worlds.md): a person
// crosses in front of a walking robot; while it is in view the map holds its
// legs' heights, and once it has left the sensors' view the rays that pass
// below those heights clear them: 2 s after it left, the score counts no
// ghost cell (a cell raised above the still scene where nothing stands now).
#include <gtest/gtest.h>

#include <string>

#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "output/terrain_files.h"

namespace proxsim {
namespace {

// raised cells of the map (above obstacle_min_m) in the box [x0, x1] × [y0, y1]
int RaisedCells(const TerrainMap& map, double x0, double x1, double y0, double y1) {
  const double r = map.grid().resolution_m();
  int raised = 0;
  for (double x = x0; x <= x1; x += r) {
    for (double y = y0; y <= y1; y += r) {
      const TerrainCell* cell = map.grid().Find(CellOf(x, y, r));
      if (cell != nullptr && cell->has_elevation() && cell->elevation_m > map.config().obstacle_min_m) ++raised;
    }
  }
  return raised;
}

TEST(GhostCells, APersonWhoCrossedInFrontLeavesNoGhostCellsTwoSecondsAfterLeavingTheView) {
  // the person crosses the robot's way at x = 1.8 (from y = −2 at t = 0.5 to
  // y = +2 at t = 4.5, where it stops, out of the forward-looking sensors' view),
  // passing the robot's line at t = 2.5 with the robot's pelvis (from x = −0.5)
  // about 1.05 m away: farther than a pedestrian yields at (kPedestrianKeep_m)
  const double left_view_t_s = 4.5;
  const Scenario scenario = LoadScenarioText(
      "proxsim: 1\nduration_s: 6.5\nrate_hz: 100\n"
      "scene:\n  objects:\n"
      "    - {name: floor, plane: {}}\n"
      "    - {name: walker, person: {height_m: 1.75}, motion: {waypoints_m: [[1.8, -2], [1.8, 2]], speed_m_s: 1, mode: once, start_s: 0.5}}\n"
      "robot:\n  start: {xyz_m: [-0.5, 0, 0]}\n  path: {waypoints_m: [[-0.5, 0], [4, 0]]}\n  on_collision: continue\n"
      "sensors:\n"
      "  - {name: ideal, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}}\n"
      "  - {name: laser, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}}\n"
      "  - {name: ideal_8, type: ideal, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 8, 0]}}\n"
      "  - {name: laser_8, type: laser, link: right_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 8, 0]}}\n"
      "",  // (a level ultrasonic beam never passes below what it saw: its echoes stay)
      "ghost.yaml");
  Simulation sim(scenario, 1);
  TerrainArchive archive(*sim.terrain_map(), false);
  int most_raised = 0;
  bool person_seen = false;
  while (!sim.done()) {
    const SampleFrame& frame = sim.Step();
    archive.Add();
    for (const SensorSample& sample : frame.sensors)
      person_seen = person_seen || (sample.reading.detected() && sim.object_name(sample.object_id).starts_with("walker/"));
    if (frame.t_s < left_view_t_s) most_raised = std::max(most_raised, RaisedCells(*sim.terrain_map(), 1.5, 2.1, -1.5, 1.5));
  }
  ASSERT_TRUE(person_seen) << "the sensors must have seen the person";
  EXPECT_GT(most_raised, 0) << "the map held the person's legs while it crossed";
  EXPECT_EQ(RaisedCells(*sim.terrain_map(), 1.5, 2.1, -1.5, 1.5), 0);
  const nlohmann::json score = RecordTerrain(archive, sim.world().caster(), "");
  ASSERT_TRUE(score.contains("ghost_cells"));
  EXPECT_EQ(score["ghost_cells"]["cells"], 0) << score.dump(2);
}

}  // namespace
}  // namespace proxsim
