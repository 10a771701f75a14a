// Compiled by the CTest `layering_strategies_and_gait_read_the_map`: the gait
// is above what the robot knows, so it may read the terrain map.
#include "gait/locomotion.h"
#include "knowledge/terrain_map.h"
