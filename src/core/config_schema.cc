#include "core/config_schema.h"

#include <charconv>
#include <cmath>

namespace proxsim {

namespace {

// the shortest text that reads back to the same double (C++17's to_chars)
std::string ShortestNumber(double value) {
  if (std::isnan(value)) return ".nan";
  if (std::isinf(value)) return value > 0 ? ".inf" : "-.inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

// a word YAML reads as the same text: letters, digits, _ . - (not a number's or a bool's look-alike is the caller's)
bool IsPlainWord(const std::string& text) {
  if (text.empty()) return false;
  for (const char c : text) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                       c == '-' || c == '.';
    if (!plain) return false;
  }
  // a word YAML would read as something else (a number, a bool, null) is quoted
  const char first = text.front();
  if ((first >= '0' && first <= '9') || first == '-' || first == '.') return false;
  for (const char* special : {"true", "false", "yes", "no", "on", "off", "null", "True", "False", "Yes", "No", "On",
                              "Off", "Null", "TRUE", "FALSE", "YES", "NO", "ON", "OFF", "NULL", "y", "n", "Y", "N"}) {
    if (text == special) return false;
  }
  return true;
}

std::string WordText(const std::string& text) {
  if (IsPlainWord(text)) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

ParamDescription Describe(std::string key, ParamType type, std::string default_text, std::string meaning) {
  ParamDescription description;
  description.key = std::move(key);
  description.type = type;
  description.default_text = std::move(default_text);
  description.meaning = std::move(meaning);
  return description;
}

bool ParamBounds::Contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (min_open ? !(value > min) : !(value >= min)) return false;
  if (max_open ? !(value < max) : !(value <= max)) return false;
  return true;
}

std::string ParamBounds::Text(const std::string& unit) const {
  const std::string suffix = unit.empty() ? "" : " " + unit;
  const bool has_min = std::isfinite(min), has_max = std::isfinite(max);
  if (has_min && has_max) {
    return std::string("in ") + (min_open ? "(" : "[") + ShortestNumber(min) + ", " + ShortestNumber(max) +
           (max_open ? ")" : "]") + suffix;
  }
  if (has_min) return std::string(min_open ? "> " : ">= ") + ShortestNumber(min) + suffix;
  if (has_max) return std::string(max_open ? "< " : "<= ") + ShortestNumber(max) + suffix;
  return unit.empty() ? "" : "in " + unit;
}

std::string ParamBounds::Expected(const std::string& unit) const {
  if (!std::isfinite(min) && !std::isfinite(max)) return "a finite number" + (unit.empty() ? "" : " in " + unit);
  return "a number " + Text(unit);
}

std::string ParamNumberText(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return ShortestNumber(value);
}

std::string ParamValueText(const ParamValue& value) {
  if (const auto* number = std::get_if<double>(&value)) return ShortestNumber(*number);
  if (const auto* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
  if (const auto* text = std::get_if<std::string>(&value)) return WordText(*text);
  std::string list;
  for (const std::string& name : std::get<std::vector<std::string>>(value)) {
    list += (list.empty() ? "" : ", ") + WordText(name);
  }
  return "[" + list + "]";
}

std::string ParamTypeText(const ParamDescription& param) {
  if (!param.type_text.empty()) return param.type_text;
  switch (param.type) {
    case ParamType::kNumber: {
      const std::string bounds = param.bounds.Text("");
      return std::string(param.whole ? "whole number" : "number") + (bounds.empty() ? "" : " " + bounds) +
             (param.unit.empty() ? "" : ", " + param.unit);
    }
    case ParamType::kFlag:
      return "`true` \\| `false`";
    case ParamType::kChoice: {
      std::string text;
      for (const std::string& choice : param.choices) text += (text.empty() ? "`" : " \\| `") + choice + "`";
      return text;
    }
    case ParamType::kText:
      return "text";
    case ParamType::kNames:
      return "list of names";
  }
  return "";
}

std::string ParamsMarkdown(const std::vector<ParamDescription>& params) {
  std::string table = "| key | type, unit | default | meaning |\n|---|---|---|---|\n";
  for (const ParamDescription& param : params) {
    table += "| `" + param.key + "` | " + ParamTypeText(param) + " | " + param.default_text + " | " + param.meaning +
             " |\n";
  }
  return table;
}

}  // namespace proxsim
