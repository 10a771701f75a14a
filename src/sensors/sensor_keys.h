// Every key a sensor takes in a scenario's `sensors` list, declared once:
// its path (`noise.sigma`), its type and unit, its default and its meaning.
// The scenario parser takes the keys it accepts from here, docs/scenario.md's
// table is `proxsim columns --sensor-keys` (a test compares them), and a test
// checks that summary.json's `sensors` echo carries each one.
#pragma once

#include <string>
#include <vector>

namespace proxsim {

struct SensorKey {
  const char* path;        ///< `key` or `parent.key`
  const char* type_unit;   ///< the value's type and unit, with its limits
  const char* default_text;
  const char* meaning;
};

/// Every sensor key, in the docs' order.
const std::vector<SensorKey>& SensorKeys();

/// The keys directly under `parent` ("" for a sensor's own keys, "noise",
/// "beam"), in order, each once.
std::vector<std::string> SensorKeyNames(const std::string& parent = "");

/// The keys as a Markdown table (key, type and unit, default, meaning).
std::string SensorKeysMarkdown();

}  // namespace proxsim
