// The geometry of the built-in scenes (internal to src/scene; the public entry
// point is MakeBuiltinScene in scene.h).
#pragma once

#include "scene/scene.h"

namespace proxsim {

/// The paper's dining room: floor, four walls, table, two chairs, cupboard and
/// a small obstacle on the robot's way (coordinates in builtin_scenes.cc).
Scene MakeDiningRoomScene();

/// A floor with a hole, then a step up and a step down (coordinates in builtin_scenes.cc).
Scene MakeStairsScene();

}  // namespace proxsim
