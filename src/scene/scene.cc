// The catalogue of built-in scenes: their names, and the factory that makes
// one by name. The geometry itself lives in builtin_scenes.cc.
#include "scene/scene.h"

#include "core/input_error.h"
#include "scene/builtin_scenes.h"

namespace proxsim {

const std::vector<std::string>& BuiltinSceneNames() {
  static const std::vector<std::string> names = {"empty", "dining_room", "stairs"};
  return names;
}

Scene MakeBuiltinScene(const std::string& name) {
  if (name == "empty") return Scene{};
  if (name == "dining_room") return MakeDiningRoomScene();
  if (name == "stairs") return MakeStairsScene();

  // unknown: list what would have been accepted
  std::string expected;
  for (const std::string& known : BuiltinSceneNames()) {
    expected += (expected.empty() ? "" : ", ") + known;
  }
  throw InputError("unknown built-in scene '" + name + "'; expected one of: " + expected);
}

}  // namespace proxsim
