// A configuration section as summary.json echoes it, by its declaration
// (core/config_schema.h): every key, an unset one as null.
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>

#include "core/config_schema.h"

namespace proxsim {

/// A value as JSON: a number, a bool, a string or a list of strings.
inline nlohmann::json ParamValueJson(const ParamValue& value) {
  return std::visit([](const auto& v) { return nlohmann::json(v); }, value);
}

/// Every key of the section (but those read by hand: the caller's); one
/// whose value means "not given" is null.
template <class Config>
nlohmann::json ParamsJson(const ConfigSchema<Config>& schema, const Config& config) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& param : schema) {
    if (param.ByHand()) continue;
    if (param.Unset(config)) {
      out[param.key()] = nullptr;
    } else if (param.description.whole) {  // a count is written as one (3, not 3.0)
      out[param.key()] = static_cast<std::int64_t>(std::get<double>(param.get(config)));
    } else {
      out[param.key()] = ParamValueJson(param.get(config));
    }
  }
  return out;
}

}  // namespace proxsim
