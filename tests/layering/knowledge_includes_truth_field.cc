// Compiled by the CTest `layering_knowledge_cannot_include_the_truth_field`:
// what the robot knows (its observations and its terrain map) is below the
// outputs that score it against the truth, so the truth field must not be
// reachable from the knowledge module.
#include "knowledge/terrain_map.h"
#include "sim/truth_field.h"
