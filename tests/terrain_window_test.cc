// The terrain map's rolling window (issue 23, map.window_m): along a long
// straight walk the map and the OctoMap tree hold a bounded number of tiles
// and nodes once the window has filled, while the files and the score, which
// read the retired tiles and subtrees back, are those of a map that never
// retires anything.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scenario/scenario.h"
#include "sim/simulation.h"
#include "output/terrain_archive.h"
#include "output/terrain_files.h"

namespace proxsim {
namespace {

// The one-hour walk's setup (tests/data/cli/long_walk.yaml), `length_m`
// long, with two low boxes beside the path and a laser turned toward them,
// for the map to find hazards that then leave its window.
Scenario StraightWalk(double length_m, double window_m) {
  std::ostringstream yaml;
  yaml << "proxsim: 1\nseed: 1\nrate_hz: 50\nduration_s: " << length_m / 0.5 + 2 << "\n"
       << "scene:\n  builtin: empty\n  objects:\n    - {name: floor, plane: {}}\n"
       << "    - {name: box_a, box: {size_m: [0.3, 0.3, 0.1]}, pose: {xyz_m: [12.0, 0.5, 0.05]}}\n"
       << "    - {name: box_b, box: {size_m: [0.3, 0.3, 0.1]}, pose: {xyz_m: [31.0, 0.5, 0.05]}}\n"
       << "robot:\n  model: builtin:biped\n  gait: {stride_m: 0.6, period_s: 1.2}\n"
       << "  path: {waypoints_m: [[0, 0], [" << length_m << ", 0]]}\n"
       << "sensors:\n"
       << "  - {name: ideal, type: ideal, link: left_tibia, pose: &mount {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 0]}}\n"
       << "  - {name: laser, type: laser, link: right_tibia, pose: *mount}\n"
       << "  - {name: ultrasonic, type: ultrasonic, link: left_tibia, pose: *mount}\n"
       << "  - {name: aside, type: laser, link: left_tibia, pose: {xyz_m: [0.06, 0, -0.35], rpy_deg: [0, 15, 30]}}\n"
       << "map: {window_m: " << window_m << "}\n";
  return LoadScenarioText(yaml.str(), "straight_walk.yaml");
}

struct WindowWalked {
  std::vector<std::size_t> tiles, octomap_nodes;  // held, every 5 m walked
  std::size_t retired_tiles = 0, retired_subtrees = 0;
  nlohmann::json score;
};

// Walks, keeps the archive as a run does, writes the files into `dir`.
WindowWalked WalkWindowed(double length_m, double window_m, const std::filesystem::path& dir) {
  WindowWalked out;
  Simulation sim(StraightWalk(length_m, window_m), 1);
  TerrainArchive archive(*sim.terrain_map(), true);
  double next_m = 5.0;
  while (!sim.done()) {
    sim.Step();
    archive.Add();
    if (sim.terrain_map()->last_position().p_W_pelvis.x() < next_m) continue;
    next_m += 5.0;
    out.tiles.push_back(sim.terrain_map()->grid().tile_count());
    out.octomap_nodes.push_back(archive.octomap()->node_count());
  }
  out.retired_tiles = archive.retired_tiles();
  out.retired_subtrees = archive.octomap()->retired_subtrees();
  out.score = RecordTerrain(archive, sim.world().caster(), dir.string());
  return out;
}

std::string Bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(TerrainWindow, MemoryStaysFlatAlongALongWalkAndTheFilesAreThoseOfAMapThatKeepsEverything) {
  const std::filesystem::path root = std::filesystem::temp_directory_path() / "proxsim_terrain_window_test";
  std::filesystem::remove_all(root);
  const double length_m = 60.0;
  const WindowWalked windowed = WalkWindowed(length_m, 3.0, root / "windowed");
  const WindowWalked unbounded = WalkWindowed(length_m, 1e9, root / "unbounded");

  // the window rolled: tiles and subtrees left memory
  ASSERT_GT(windowed.retired_tiles, 100u);
  ASSERT_GT(windowed.retired_subtrees, 5u);
  EXPECT_EQ(unbounded.retired_tiles, 0u);
  ASSERT_GE(windowed.tiles.size(), 10u);
  // flat once the window (3 m behind, what the sensors see ahead) has filled,
  // by 10 m walked: never more than the most held then, plus a tile column
  // of slack per side; the map that keeps everything grows with the walk
  const std::size_t filled_tiles = *std::max_element(windowed.tiles.begin(), windowed.tiles.begin() + 2);
  const std::size_t filled_nodes = *std::max_element(windowed.octomap_nodes.begin(), windowed.octomap_nodes.begin() + 2);
  for (std::size_t k = 2; k < windowed.tiles.size(); ++k) {
    EXPECT_LE(windowed.tiles[k], filled_tiles + 8) << "at " << 5 * (k + 1) << " m";
    // the tree holds up to two 5.12 m columns of subtrees more than at 10 m
    EXPECT_LE(windowed.octomap_nodes[k], 2 * filled_nodes) << "at " << 5 * (k + 1) << " m";
  }
  EXPECT_GT(unbounded.tiles.back(), 4 * windowed.tiles.back());
  EXPECT_GT(unbounded.octomap_nodes.back(), 3 * windowed.octomap_nodes.back());

  // the files are byte for byte those of the map that kept everything
  for (const char* name : {"elevation.npy", "variance.npy", "upper_bound.npy", "truth.npy", "hits.npy",
                           "first_update_t_s.npy", "last_update_t_s.npy", "meta.json", "hazards.csv", "map.bt"}) {
    const std::string a = Bytes(root / "windowed" / name), b = Bytes(root / "unbounded" / name);
    EXPECT_GT(a.size(), 0u) << name;
    EXPECT_TRUE(a == b) << name << " differs (" << a.size() << " and " << b.size() << " bytes)";
  }
  // and so is the score, but for what the map held at the end
  nlohmann::json a = windowed.score, b = unbounded.score;
  for (nlohmann::json* score : {&a, &b}) score->erase("map_memory_bytes"), score->erase("map_tiles");
  EXPECT_EQ(a, b) << a.dump(1) << "\n" << b.dump(1);
  EXPECT_GT(a["cells_measured"].get<std::size_t>(), 2000u);
  EXPECT_GE(a["hazards"]["mapped"].get<std::size_t>(), 1u) << "a box beside the path";
  std::filesystem::remove_all(root);
}

TEST(TerrainWindow, AWindowBelowOneMetreIsRefusedAtItsKey) {
  TerrainMapConfig config;
  config.window_m = 0.5;
  const std::vector<std::string> problems = config.Validate();
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].rfind("window_m: ", 0), 0u) << problems[0];
}

}  // namespace
}  // namespace proxsim
