// Compiled by the CTest `layering_strategies_and_gait_read_the_map`: every
// strategy may read the terrain map the robot built (Observation::map).
#include "knowledge/terrain_map.h"
#include "strategy/strategy.h"

namespace proxsim {
// the map's heights, from a strategy's side of the build
double HeightAtForProbe(const Observation& observation, double x_m, double y_m) {
  const TerrainCell* cell = observation.map != nullptr ? observation.map->CellAt(x_m, y_m) : nullptr;
  return cell != nullptr && cell->has_elevation() ? cell->elevation_m : 0.0;
}
}  // namespace proxsim
