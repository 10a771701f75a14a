// The catalogue of built-in scenes: their names, and the factory that makes
// one by name. The geometry itself lives in builtin_scenes.cc.
#include "scene/scene.h"

#include "core/input_error.h"
#include "scene/builtin_scenes.h"

namespace proxsim {

const ConfigSchema<Material>& MaterialSchema() {
  using C = Material;
  // an optional value: absent means the text given
  const auto optional = [](const char* key, std::optional<double> C::*member, const char* absent, const char* meaning) {
    return ConvertedNumberParam<C>(
        key, Between(0, 1), "", absent, meaning, [member](const C& c) { return (c.*member).value_or(0.0); },
        [member](C& c, double v) { c.*member = v; }, [member](const C& c) { return !(c.*member).has_value(); });
  };
  static const ConfigSchema<C> schema = {
      NumberParam("albedo", &C::albedo, Between(0, 1), "", "the diffuse reflectance"),
      NumberParam("specular", &C::specular, Between(0, 1), "", "the specular fraction of the reflection"),
      optional("ir_albedo", &C::ir_albedo, "`albedo`", "what infra-red sensors see"),
      optional("acoustic_reflectivity", &C::acoustic_reflectivity, "1", "the fraction of sound returned"),
  };
  return schema;
}

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
