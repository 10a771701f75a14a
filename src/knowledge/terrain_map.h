// The terrain map the robot builds while it walks, from what it knows only:
// every sample, each fresh reading of the sensors that feed the map becomes
// a point and an empty ray (ray_evidence.h) in the elevation grid
// (elevation_grid.h), and the hazards (hazards.h) are found again, relative
// to the ground the robot stands on, whenever a cell's label changed (at most
// every 20 ms). A silent ray stops where it comes within 8 cm of the robot's
// own feet (its kinematics say where they are): a grazing foot sends no echo
// back, and the ray says nothing beyond it. A hazard keeps the time it was first detected, and the
// leading toe's distance to it then, while later passes grow or reclassify
// it. Strategies read it through Observation::map.
//
// The map is a rolling window (`map.window_m`): whenever the robot has moved
// a tile's side, the tiles with no cell within window_m of its pelvis (in x
// or y) leave the map, and with them the hazards all of whose tiles are
// outside (a tile under a hazard that is not wholly outside stays, so that a
// hazard leaves whole, as it was found). They are
// handed over for one sample (last_retired_tiles(), last_retired_hazards()),
// for the outputs to keep (terrain_archive.h); the map forgets them. Where the
// robot comes back, the map starts that ground anew.
//
// Frames: W world, S a sensor.
#pragma once

#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "sensors/sensor_spec.h"
#include "knowledge/observation.h"
#include "knowledge/elevation_grid.h"
#include "knowledge/hazards.h"
#include "knowledge/ray_evidence.h"
#include "knowledge/terrain_config.h"

namespace proxsim {

/// Where the robot is: the map's last position, which the outputs keep as the
/// track (every centimetre walked, and when the ground it stands on changes).
struct TrackPoint {
  double t_s = 0.0;
  Vec2 p_W_pelvis = Vec2::Zero();
  Vec2 p_W_front = Vec2::Zero();    ///< the leading toe
  Vec2 heading_W = Vec2::UnitX();   ///< unit
  double ground_z_m = 0.0;          ///< the ground it stood on
};

class TerrainMap {
 public:
  /// The hazards are looked for again at most this often.
  static constexpr double kHazardPeriod_s = 0.02;

  /// `specs[i]` is sensor i's datasheet; `feeds_map[i]` whether its readings go into the map.
  TerrainMap(const TerrainMapConfig& config, std::vector<SensorSpec> specs, std::vector<bool> feeds_map);

  /// A new episode: an empty map.
  void Reset();

  /// One sample: the observation's fresh readings into the grid, then the
  /// hazards if due. Requires observation.robot. `columns`: vertical rays
  /// of perfect perception (map.truth_within_m, the oracle baseline; the
  /// simulation computes them from the scene), inserted as they are.
  void Update(const Observation& observation, std::span<const RayEvidence> columns = {});

  const TerrainMapConfig& config() const { return config_; }
  const ElevationGrid& grid() const { return grid_; }
  /// The cell holding world point (x, y), or null when it is still unknown land.
  const TerrainCell* CellAt(double x_m, double y_m) const { return grid_.Find(grid_.IndexOf(x_m, y_m)); }
  /// The hazards found so far (the last pass's, and those left behind on
  /// another ground), within the window.
  const std::vector<Hazard>& hazards() const { return hazards_; }
  /// How many clusters the last hazard pass kept from the pass before, and
  /// how many it filled again (FindHazardsAgain): what its incremental work saved.
  std::size_t clusters_kept_at_last_pass() const { return clusters_kept_; }
  std::size_t clusters_filled_at_last_pass() const { return clusters_.size() - clusters_kept_; }
  /// The tiles and hazards that left the window at the last sample.
  const std::vector<std::unique_ptr<ElevationGrid::Tile>>& last_retired_tiles() const { return retired_tiles_; }
  const std::vector<Hazard>& last_retired_hazards() const { return retired_hazards_; }
  /// What the last sample's readings said, one entry per fresh reading of a map sensor.
  std::span<const RayEvidence> last_evidence() const { return evidence_; }
  /// Whether sensor i's readings feed the map.
  bool feeds_map(std::size_t sensor) const { return feeds_map_[sensor]; }
  /// Where the robot was at the last sample.
  const TrackPoint& last_position() const { return last_; }
  double last_t_s() const { return last_.t_s; }

 private:
  // one ray's evidence: clipped at the robot's feet when silent, kept for the viewer, inserted
  void AddEvidence(RayEvidence evidence, const Observation& observation);
  void Insert(const RayEvidence& evidence, double t_s, double ceiling_z_m);
  void UpdatePosition(double t_s, const RobotKnowledge& robot);
  // retires the tiles and hazards beyond the window, when the robot moved a tile's side since the last time
  void RollWindow();
  // relabel changed tiles; true if a label changed
  bool Relabel(double ground_z_m);
  void FindHazardsAgain(double t_s, const RobotKnowledge& robot);

  // a cluster of labelled cells found by a hazard pass: its cells in the
  // order the fill visited them (the first is its least in row order), their
  // surfaces then, and its hazard as classified, before matching with the
  // hazards known
  struct Cluster {
    std::vector<CellIndex> cells;
    std::vector<CellSurface> surfaces;
    Hazard hazard;
  };

  TerrainMapConfig config_;
  std::vector<SensorSpec> specs_;
  std::vector<bool> feeds_map_;
  std::vector<EvidenceModel> models_;  // specs_[i]'s, found once
  ElevationGrid grid_;
  std::vector<RayEvidence> evidence_;
  std::vector<Hazard> hazards_;
  std::vector<std::unique_ptr<ElevationGrid::Tile>> retired_tiles_;
  std::vector<Hazard> retired_hazards_;
  TrackPoint last_;
  Vec2 rolled_at_W_ = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());  // where the window last rolled
  double labelled_ground_z_m_ = 0.0;
  // the last hazard pass's clusters, the ground they were found against, and
  // whether tiles left the window since (then every cluster is found again)
  std::vector<Cluster> clusters_;
  double clustered_ground_z_m_ = std::numeric_limits<double>::quiet_NaN();
  std::size_t clusters_kept_ = 0;  // of clusters_, those the last pass kept
  bool retired_since_pass_ = false;
  // the cells relabelled since the last hazard pass
  std::vector<CellIndex> relabelled_;
  // the hazard pass's scratch: the known hazards by tile (TileKey, index), those near one found
  std::vector<std::pair<std::uint64_t, std::size_t>> by_tile_;
  std::vector<std::size_t> near_;
  bool labels_changed_ = false;
  double next_pass_t_s_ = 0.0;
};

}  // namespace proxsim
