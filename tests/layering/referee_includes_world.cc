// Compiled by the CTest `layering_referee_cannot_include_the_world`: the
// referee judges from the facts the simulation tells it; the world, its ray
// caster and the sensor rig (sim/) lie above it.
#include "referee/referee.h"
#include "sim/world.h"
