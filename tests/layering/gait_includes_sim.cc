// Compiled by the CTest `layering_wrong_way_include_fails`: the gait is below
// the simulation, so including the simulation from the gait must not compile.
#include "gait/gait_walker.h"
#include "sim/world.h"
