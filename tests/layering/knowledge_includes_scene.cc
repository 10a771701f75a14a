// Compiled by the CTest `layering_knowledge_cannot_include_the_scene`: the
// knowledge module sees core and sensors only; the scene (the world's true
// geometry) must not be reachable from what the robot knows.
#include "knowledge/observation.h"
#include "scene/scene.h"
