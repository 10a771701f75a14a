// The mechanics of reading a YAML document value by value: type checks,
// finiteness and bounds for numbers, map keys against a schema. yaml-cpp marks
// every node with its position; its lines count from 0, ours from 1.
#include "scenario/yaml_reader.h"

#include "core/input_error.h"
#include "core/input_limits.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/nearest_key.h"
#include "core/nesting_scan.h"

namespace proxsim {

namespace {

// yaml-cpp gives quoted scalars the non-specific tag "!", plain ones "?".
bool IsQuotedScalar(const YAML::Node& node) { return node.IsScalar() && node.Tag() == "!"; }

// The 1-based line of a node, 0 when yaml-cpp has no position for it.
int LineOf(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

std::string FormatNumber(double value) {
  // what `std::ostringstream() << value` writes (its default: %g, 6 digits,
  // in the C locale, which proxsim never changes), without building a
  // stream: the number rules' messages are formatted for every field read
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string WithUnit(std::string text, const std::string& unit) {
  return unit.empty() ? text : text + " " + unit;
}

std::string JoinWords(const std::vector<std::string>& words) {
  std::string all;
  for (const auto& word : words) all += (all.empty() ? "" : ", ") + word;
  return all;
}

}  // namespace

NumberRule AnyNumber() { return NumberRule{}; }

NumberRule PositiveNumber(const std::string& unit) {
  NumberRule rule;
  rule.min = 0;
  rule.min_exclusive = true;
  rule.expected = WithUnit("a finite number > 0", unit);
  return rule;
}

NumberRule NonNegativeNumber(const std::string& unit) {
  NumberRule rule;
  rule.min = 0;
  rule.expected = WithUnit("a finite number >= 0", unit);
  return rule;
}

NumberRule Coordinate() {
  NumberRule rule = NumberIn(-kMaxCoordinate_m, kMaxCoordinate_m, "m");
  rule.expected += " (the coordinate limit: rays are cast in single precision; docs/trust.md)";
  return rule;
}

NumberRule PositiveLength() {
  NumberRule rule = PositiveNumber("m");
  rule.max = 2 * kMaxCoordinate_m;
  rule.expected = "a finite number at most " + FormatNumber(rule.max) +
                  " m (the coordinate limit: rays are cast in single precision; docs/trust.md) and > 0 m";
  return rule;
}

NumberRule NumberIn(double min, double max, const std::string& unit) {
  NumberRule rule;
  rule.min = min;
  rule.max = max;
  rule.expected = WithUnit("a number in [" + FormatNumber(min) + ", " + FormatNumber(max) + "]", unit);
  return rule;
}

std::string DescribeNode(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsScalar()) {
    std::string text = node.Scalar();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return IsQuotedScalar(node) ? "\"" + text + "\"" : text;
  }
  if (node.IsMap()) return "a map";
  // a short flat list is shown whole, anything bigger is summarised
  const bool flat = std::all_of(node.begin(), node.end(), [](const YAML::Node& item) { return item.IsScalar(); });
  if (!flat || node.size() > 8) return "a list of " + std::to_string(node.size()) + " items";
  std::string text = "[";
  for (std::size_t i = 0; i < node.size(); ++i) text += (i ? ", " : "") + DescribeNode(node[i]);
  return text + "]";
}

std::string JoinPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

Field MapView::operator[](const std::string& key) const {
  assert(std::find(schema_keys_.begin(), schema_keys_.end(), key) != schema_keys_.end() &&
         "asked for a key outside the map's schema");
  for (const auto& [name, value] : entries_) {
    if (name == key) return Field{value, JoinPath(field_.path, key), true};
  }
  return Field{field_.node, JoinPath(field_.path, key), false};
}

bool MapView::Has(const std::string& key) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const auto& entry) { return entry.first == key; });
}

void YamlReader::Fail(const Field& field, const std::string& message) {
  FailAtLine(LineOf(field.node), field.path, message);
}

YAML::Node YamlReader::Parse(const std::string& text) {
  // yaml-cpp recurses per level and says only "bad file" past its own limit: the depth named first
  if (const NestingScan scan = ScanYamlNesting(text, kMaxNestingDepth); scan.too_deep_at > 0) {
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(scan.too_deep_at), '\n'));
    FailAtLine(line, "", "YAML nested deeper than " + std::to_string(kMaxNestingDepth) +
                             " levels (flow [ and { inside block maps and lists); proxsim refuses such files before "
                             "parsing them (limit: " + std::to_string(kMaxNestingDepth) + " levels, docs/trust.md)");
    throw InputError(Problems());
  }
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& error) {
    FailAtLine(error.mark.is_null() ? 0 : error.mark.line + 1, "", "not valid YAML: " + error.msg);
    throw InputError(Problems());
  }
}

void YamlReader::FailFile(const std::string& message) { problems_.emplace_back(0, source_ + ": " + message); }

void YamlReader::FailAtLine(int line, const std::string& path, const std::string& message) {
  std::string text = source_;
  // two appends, not `":" + std::to_string(line)`: GCC 12 misreads that
  // temporary's insert as an overlapping memcpy (a false -Wrestrict at -O3)
  if (line > 0) {
    text += ':';
    text += std::to_string(line);
  }
  text += ": ";
  if (!path.empty()) text += path + ": ";
  problems_.emplace_back(line, text + message);
}

std::vector<std::string> YamlReader::Problems() const {
  auto by_line = problems_;
  std::stable_sort(by_line.begin(), by_line.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> messages;
  for (auto& [line, message] : by_line) messages.push_back(std::move(message));
  return messages;
}

std::optional<MapView> YamlReader::Map(const Field& field, std::vector<std::string> schema_keys,
                                       const std::string& expected) {
  MapView view(field, std::move(schema_keys));
  if (!field || field.node.IsNull()) return view;
  if (!field.node.IsMap()) {
    const std::string what = expected.empty() ? "a map with keys " + JoinWords(view.schema_keys_) : expected;
    Fail(field, "expected " + what + ", got " + DescribeNode(field.node));
    return std::nullopt;
  }
  // every key must be in the schema, and appear once
  for (auto it = field.node.begin(); it != field.node.end(); ++it) {
    // copies: the iterator hands out a temporary key/value pair
    const YAML::Node key = it->first;
    const YAML::Node value = it->second;
    if (!key.IsScalar()) {
      Fail(Field{key, field.path, true}, "expected a plain key, got " + DescribeNode(key));
      continue;
    }
    const std::string& name = key.Scalar();
    const Field key_field{key, JoinPath(field.path, name), true};
    const auto& keys = view.schema_keys_;
    if (std::find(keys.begin(), keys.end(), name) == keys.end()) {
      const auto nearest = NearestKey(name, keys);
      const std::string hint = nearest       ? "did you mean '" + *nearest + "'?"
                               : keys.empty() ? "this map takes no keys"
                                              : "expected one of " + JoinWords(keys);
      Fail(key_field, "unknown key '" + name + "' (" + hint + ")");
      continue;
    }
    if (view.Has(name)) {
      Fail(key_field, "duplicate key '" + name + "'");
      continue;
    }
    view.entries_.emplace_back(name, value);
  }
  return view;
}

std::optional<std::vector<Field>> YamlReader::List(const Field& field, const std::string& expected) {
  std::vector<Field> items;
  if (!field || field.node.IsNull()) return items;
  if (!field.node.IsSequence()) {
    Fail(field, "expected " + expected + ", got " + DescribeNode(field.node));
    return std::nullopt;
  }
  for (std::size_t i = 0; i < field.node.size(); ++i) {
    items.push_back(Field{field.node[i], field.path + "[" + std::to_string(i) + "]", true});
  }
  return items;
}

bool YamlReader::Require(const Field& field, const std::string& expected) {
  if (!field) Fail(field, "missing; expected " + expected);
  return field.present;
}

std::optional<double> YamlReader::Number(const Field& field, const NumberRule& rule) {
  if (!field) return std::nullopt;
  double value = 0;
  const bool parsed = field.node.IsScalar() && !IsQuotedScalar(field.node) &&
                      YAML::convert<double>::decode(field.node, value);
  const bool in_bounds = parsed && std::isfinite(value) && value >= rule.min && value <= rule.max &&
                         !(rule.min_exclusive && value == rule.min);
  if (!in_bounds) {
    Fail(field, "expected " + rule.expected + ", got " + DescribeNode(field.node));
    return std::nullopt;
  }
  return value;
}

std::optional<std::uint64_t> YamlReader::Count(const Field& field) {
  if (!field) return std::nullopt;
  // decimal digits only: no sign, no fraction, no exponent, no hexadecimal
  std::uint64_t value = 0;
  bool parsed = false;
  if (field.node.IsScalar() && !IsQuotedScalar(field.node)) {
    const std::string& text = field.node.Scalar();
    const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    parsed = digits && error == std::errc() && end == text.data() + text.size();
  }
  if (!parsed) {
    Fail(field, "expected a whole number >= 0, got " + DescribeNode(field.node));
    return std::nullopt;
  }
  return value;
}

std::optional<bool> YamlReader::Bool(const Field& field) {
  if (!field) return std::nullopt;
  bool value = false;
  if (!field.node.IsScalar() || IsQuotedScalar(field.node) || !YAML::convert<bool>::decode(field.node, value)) {
    Fail(field, "expected true or false, got " + DescribeNode(field.node));
    return std::nullopt;
  }
  return value;
}

std::optional<std::string> YamlReader::String(const Field& field, bool non_empty) {
  if (!field) return std::nullopt;
  if (!field.node.IsScalar() || (non_empty && field.node.Scalar().empty())) {
    Fail(field, std::string("expected ") + (non_empty ? "a non-empty text" : "a text") + ", got " +
                    DescribeNode(field.node));
    return std::nullopt;
  }
  return field.node.Scalar();
}

std::optional<std::vector<double>> YamlReader::Numbers(const Field& field, std::size_t count,
                                                       const NumberRule& element, const std::string& expected) {
  if (!field) return std::nullopt;
  if (!field.node.IsSequence() || field.node.size() != count) {
    Fail(field, "expected " + expected + ", got " + DescribeNode(field.node));
    return std::nullopt;
  }
  // check every element, so that each bad one is reported
  std::vector<double> values;
  bool all_valid = true;
  for (std::size_t i = 0; i < count; ++i) {
    const auto value = Number(Field{field.node[i], field.path + "[" + std::to_string(i) + "]", true}, element);
    all_valid = all_valid && value.has_value();
    values.push_back(value.value_or(0.0));
  }
  if (!all_valid) return std::nullopt;
  return values;
}

std::optional<Vec3> YamlReader::Vector3(const Field& field, const NumberRule& element, const std::string& expected) {
  const auto values = Numbers(field, 3, element, expected);
  if (!values) return std::nullopt;
  return Vec3((*values)[0], (*values)[1], (*values)[2]);
}

}  // namespace proxsim
