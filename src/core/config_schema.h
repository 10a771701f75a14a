// One declaration per configuration section: each key's member, type, unit,
// bounds and meaning, written once beside the section's struct (its default
// is the struct's own initializer). The declaration drives
//   - the keys the scenario reader accepts and its unknown-key messages, and
//     the reading of each value by its type (scenario/param_reader.h);
//   - the bounds the struct's Validate() checks (CheckParamBounds);
//   - the summary.json echo (sim/params_json.h): every key, complete by
//     construction;
//   - the docs' tables (`proxsim columns --keys SECTION`, ParamsMarkdown);
//   - a YAML writer (ParamsYaml), whose text reads back to the same values.
// Adding a key to a section is one line here plus its use.
//
// Nothing here reads a file: this is the bottom layer, so that the knowledge,
// gait and strategy modules can declare their own sections.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace proxsim {

/// A parameter's value as the schema moves it between a struct and a file.
using ParamValue = std::variant<double, bool, std::string, std::vector<std::string>>;

/// The interval a number must lie in (always finite as well).
struct ParamBounds {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< true: > min, not >= min
  bool max_open = false;  ///< true: < max, not <= max

  bool Contains(double value) const;
  /// "> 0 m", ">= 1 m", "in [0.005, 1] m", "in (0, 180) deg", or "" when any finite number goes.
  std::string Text(const std::string& unit) const;
  /// What a message expects: "a number > 0 m", or "a finite number in m".
  std::string Expected(const std::string& unit) const;
};

/// Any finite number.
inline ParamBounds AnyFinite() { return {}; }
/// > 0.
inline ParamBounds Positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
/// >= 0.
inline ParamBounds NonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
/// >= min.
inline ParamBounds AtLeast(double min) { return {min, std::numeric_limits<double>::infinity(), false, false}; }
/// In [min, max].
inline ParamBounds Between(double min, double max) { return {min, max, false, false}; }

enum class ParamType {
  kNumber,  ///< a finite number within its bounds, in its unit
  kFlag,    ///< true or false
  kChoice,  ///< one of a list of words
  kText,    ///< any non-empty text
  kNames,   ///< a list of names
};

/// What a section's parameter is, without the struct it lives in: for the
/// docs' tables and the Python package.
struct ParamDescription {
  std::string key;
  ParamType type = ParamType::kNumber;
  std::string unit;
  ParamBounds bounds;
  std::vector<std::string> choices;
  std::vector<std::string> choice_glosses;  ///< what each choice does, for messages (empty, or one per choice)
  std::string default_text;  ///< the default as a file would write it, or what leaving it out means
  std::string meaning;
  std::string bounds_note;   ///< why the bounds are what they are, for messages ("" for none)
  bool whole = false;        ///< a number: a whole number (read as a count)
  std::string type_text;     ///< the type as the docs say it, for a key read by its section's own code
};

/// A description with its key, type, default and meaning; the rest (unit,
/// bounds, choices, notes) set by the caller.
ParamDescription Describe(std::string key, ParamType type, std::string default_text, std::string meaning);

/// One key of a section of struct `Config`.
template <class Config>
struct ConfigParam {
  ParamDescription description;
  std::function<ParamValue(const Config&)> get;
  std::function<void(Config&, const ParamValue&)> set;
  /// The value means "not given" (e.g. 0 for "from the legs"): echoed null,
  /// not written. Empty for a parameter that always has a value.
  std::function<bool(const Config&)> is_unset;

  const std::string& key() const { return description.key; }
  bool Unset(const Config& config) const { return is_unset && is_unset(config); }
  /// A key the section's own code reads, echoes and writes (a nested map, a
  /// path resolved against the file): declared here for the key list and the docs.
  bool ByHand() const { return !get; }
};

template <class Config>
using ConfigSchema = std::vector<ConfigParam<Config>>;

/// A value as a file writes it: a number in its shortest form that reads back
/// to the same double, true/false, a word, or a flow list [a, b].
std::string ParamValueText(const ParamValue& value);

/// A number for a message: as ParamValueText, but inf and nan as such.
std::string ParamNumberText(double value);

/// "number > 0, m", "`readings` \| `map`", "true \| false", "list of names".
std::string ParamTypeText(const ParamDescription& param);

/// The Markdown table of a section's keys: key, type and unit, default, meaning.
std::string ParamsMarkdown(const std::vector<ParamDescription>& params);

// --- declaring a parameter -------------------------------------------------

/// A number member, always given (its default is the struct's initializer).
template <class Config>
ConfigParam<Config> NumberParam(std::string key, double Config::*member, ParamBounds bounds, std::string unit,
                                std::string meaning) {
  ConfigParam<Config> param;
  param.description = Describe(std::move(key), ParamType::kNumber, ParamValueText(Config{}.*member), std::move(meaning));
  param.description.unit = std::move(unit);
  param.description.bounds = bounds;
  param.get = [member](const Config& c) { return ParamValue(c.*member); };
  param.set = [member](Config& c, const ParamValue& v) { c.*member = std::get<double>(v); };
  return param;
}

/// A number member whose default (the struct's initializer) stands for
/// "not given", which means `unset_means` (e.g. "the legs' gait.max_step_m").
template <class Config>
ConfigParam<Config> OptionalNumberParam(std::string key, double Config::*member, ParamBounds bounds, std::string unit,
                                        std::string unset_means, std::string meaning) {
  ConfigParam<Config> param = NumberParam(std::move(key), member, bounds, std::move(unit), std::move(meaning));
  param.description.default_text = std::move(unset_means);
  const double unset = Config{}.*member;
  param.is_unset = [member, unset](const Config& c) { return c.*member == unset; };
  return param;
}

/// A number the file gives in `unit` and the struct keeps its own way (another
/// unit, an optional, a flag beside it): `get` and `set` convert, `is_unset`
/// (may be empty) says the struct holds "not given", which means `default_text`.
template <class Config>
ConfigParam<Config> ConvertedNumberParam(std::string key, ParamBounds bounds, std::string unit,
                                         std::string default_text, std::string meaning,
                                         std::function<double(const Config&)> get,
                                         std::function<void(Config&, double)> set,
                                         std::function<bool(const Config&)> is_unset = {}) {
  ConfigParam<Config> param;
  param.description = Describe(std::move(key), ParamType::kNumber, std::move(default_text), std::move(meaning));
  param.description.unit = std::move(unit);
  param.description.bounds = bounds;
  param.get = [get](const Config& c) { return ParamValue(get(c)); };
  param.set = [set](Config& c, const ParamValue& v) { set(c, std::get<double>(v)); };
  param.is_unset = std::move(is_unset);
  return param;
}

/// A text member; empty (the default) means `unset_means`.
template <class Config>
ConfigParam<Config> TextParam(std::string key, std::string Config::*member, std::string unset_means,
                              std::string meaning) {
  ConfigParam<Config> param;
  param.description = Describe(std::move(key), ParamType::kText, std::move(unset_means), std::move(meaning));
  param.get = [member](const Config& c) { return ParamValue(c.*member); };
  param.set = [member](Config& c, const ParamValue& v) { c.*member = std::get<std::string>(v); };
  param.is_unset = [member](const Config& c) { return (c.*member).empty(); };
  return param;
}

/// A key read by its section's own code (see ConfigParam::ByHand): its type
/// as the docs say it, its default and meaning.
template <class Config>
ConfigParam<Config> ByHandParam(std::string key, std::string type_text, std::string default_text, std::string meaning) {
  ConfigParam<Config> param;
  param.description = Describe(std::move(key), ParamType::kText, std::move(default_text), std::move(meaning));
  param.description.type_text = std::move(type_text);
  return param;
}

/// A bool member.
template <class Config>
ConfigParam<Config> FlagParam(std::string key, bool Config::*member, std::string meaning) {
  ConfigParam<Config> param;
  param.description = Describe(std::move(key), ParamType::kFlag, ParamValueText(Config{}.*member), std::move(meaning));
  param.get = [member](const Config& c) { return ParamValue(c.*member); };
  param.set = [member](Config& c, const ParamValue& v) { c.*member = std::get<bool>(v); };
  return param;
}

/// An enum member, by the names a file gives it (`names`: every value once).
template <class Config, class Enum>
ConfigParam<Config> ChoiceParam(std::string key, Enum Config::*member, std::vector<std::pair<Enum, std::string>> names,
                                std::string meaning) {
  ConfigParam<Config> param;
  std::vector<std::string> choices;
  std::string default_name;
  for (const auto& [value, name] : names) {
    choices.push_back(name);
    if (value == Config{}.*member) default_name = name;
  }
  param.description = Describe(std::move(key), ParamType::kChoice, default_name, std::move(meaning));
  param.description.choices = std::move(choices);
  param.get = [member, names](const Config& c) {
    for (const auto& [value, name] : names)
      if (value == c.*member) return ParamValue(name);
    return ParamValue(std::string());
  };
  param.set = [member, names](Config& c, const ParamValue& v) {
    for (const auto& [value, name] : names)
      if (name == std::get<std::string>(v)) c.*member = value;
  };
  return param;
}

/// `param` with the reason its bounds are what they are, for messages.
template <class Config>
ConfigParam<Config> WithNote(ConfigParam<Config> param, std::string bounds_note) {
  param.description.bounds_note = std::move(bounds_note);
  return param;
}

/// `param` (a choice) with what each choice does, in the choices' order, for messages.
template <class Config>
ConfigParam<Config> WithGlosses(ConfigParam<Config> param, std::vector<std::string> glosses) {
  param.description.choice_glosses = std::move(glosses);
  return param;
}

/// `param` (a number) as a whole number: read as a count, echoed as one.
template <class Config>
ConfigParam<Config> AsWhole(ConfigParam<Config> param) {
  param.description.whole = true;
  return param;
}

// --- using a declaration ---------------------------------------------------

/// The keys, in the declaration's order.
template <class Config>
std::vector<std::string> ParamKeys(const ConfigSchema<Config>& schema) {
  std::vector<std::string> keys;
  for (const auto& param : schema) keys.push_back(param.key());
  return keys;
}

/// The declarations without the struct.
template <class Config>
std::vector<ParamDescription> DescribeParams(const ConfigSchema<Config>& schema) {
  std::vector<ParamDescription> out;
  for (const auto& param : schema) out.push_back(param.description);
  return out;
}

/// "KEY: expected a number > 0 m, got X" for each number out of its bounds
/// (an unset one is not judged), in the declaration's order.
template <class Config>
std::vector<std::string> CheckParamBounds(const ConfigSchema<Config>& schema, const Config& config) {
  std::vector<std::string> problems;
  for (const auto& param : schema) {
    if (param.ByHand() || param.description.type != ParamType::kNumber || param.Unset(config)) continue;
    const double value = std::get<double>(param.get(config));
    if (!param.description.bounds.Contains(value)) {
      const std::string& note = param.description.bounds_note;
      const ParamDescription& d = param.description;
      const std::string expected =
          d.whole ? "a whole number " + d.bounds.Text(d.unit) : d.bounds.Expected(d.unit);
      problems.push_back(param.key() + ": expected " + expected +
                         (note.empty() ? "" : " (" + note + ")") + ", got " + ParamNumberText(value));
    }
  }
  return problems;
}

/// The section as a YAML flow map, `{key: value, ...}`, every key that has a
/// value (but those read by hand), in the declaration's order; `first` goes before them (e.g. a
/// strategy's `name: stop`). It reads back to the same values.
template <class Config>
std::string ParamsYaml(const ConfigSchema<Config>& schema, const Config& config, const std::string& first = "") {
  std::string text = first;
  for (const auto& param : schema) {
    if (param.ByHand() || param.Unset(config)) continue;
    text += (text.empty() ? "" : ", ") + param.key() + ": " + ParamValueText(param.get(config));
  }
  return "{" + text + "}";
}

}  // namespace proxsim
