// Reading a configuration section by its declaration (core/config_schema.h):
// the keys it accepts, each value by its type; the bounds are the section's
// Validate()'s, reported at the keys that gave the values.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/config_schema.h"
#include "scenario/yaml_reader.h"

namespace proxsim {

/// The value of `field` read as `param`'s type (a number only checked finite:
/// its bounds are Validate()'s); nullopt after reporting when it is not one.
std::optional<ParamValue> ReadParamValue(YamlReader& reader, const Field& field, const ParamDescription& param);

/// Opens `field` as a map of the schema's keys (and `extra_keys`, read by the caller).
template <class Config>
std::optional<MapView> OpenSection(YamlReader& reader, const Field& field, const ConfigSchema<Config>& schema,
                                   const std::vector<std::string>& extra_keys = {}) {
  std::vector<std::string> keys = extra_keys;
  for (const std::string& key : ParamKeys(schema)) keys.push_back(key);
  return reader.Map(field, keys);
}

/// Every key of the schema the file gives, read into `config` (but those read
/// by hand: the caller's); the others keep their defaults.
template <class Config>
void ReadParams(YamlReader& reader, const MapView& map, const ConfigSchema<Config>& schema, Config& config) {
  for (const auto& param : schema) {
    if (param.ByHand()) continue;
    const Field field = map[param.key()];
    if (!field) continue;
    if (const auto value = ReadParamValue(reader, field, param.description)) param.set(config, *value);
  }
}

/// Validate()'s problems, "KEY: message" each, reported at KEY's line when the
/// file gave it, at the section's otherwise.
void ReportAtKeys(YamlReader& reader, const MapView& map, const std::vector<std::string>& problems);

}  // namespace proxsim
