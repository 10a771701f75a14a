// Compiled by the CTest `layering_right_way_include_builds`: the simulation
// may read the gait, the layer below it.
#include "gait/gait_walker.h"
#include "sim/world.h"
