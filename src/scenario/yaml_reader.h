// Typed, line-aware access to a parsed YAML document, for validating input
// files. Nothing here throws on bad input: every problem is recorded as
// "FILE:LINE: KEY.PATH: what was expected, got what was there", and reading
// carries on so that one pass reports everything. The caller throws the
// collected problems as one InputError at the end.
//
// A value is read through a Field (the node, its full key path, and whether
// the key was present at all); a map is opened through a MapView, which has
// already reported its unknown keys (with the nearest valid key suggested)
// and duplicate keys. An absent optional key is not a problem: the reader
// returns nullopt and the caller keeps its default.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/geometry.h"

namespace proxsim {

/// One value of the document: where it is and what it is called. (Copy it,
/// never assign to one: yaml-cpp's Node::operator= writes into the document.)
struct Field {
  YAML::Node node;       ///< the value; when absent, the enclosing map (for its line)
  std::string path;      ///< full key path, e.g. "sensors[1].range_m"; empty for the document
  bool present = false;  ///< false when the key is missing from its map
  explicit operator bool() const { return present; }
};

/// Bounds a number must satisfy, and how to say so in a message.
struct NumberRule {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;           ///< true: the value must be > min, not >= min
  std::string expected = "a finite number";  ///< completes "expected …"
};

/// Any finite number.
NumberRule AnyNumber();
/// A finite number > 0, e.g. "a length > 0 m" with unit "m".
NumberRule PositiveNumber(const std::string& unit = "");
/// A finite number >= 0.
NumberRule NonNegativeNumber(const std::string& unit = "");
/// A finite number in [min, max].
NumberRule NumberIn(double min, double max, const std::string& unit = "");
/// A position in metres within ±kMaxCoordinate_m (core/input_limits.h): rays
/// are cast in single precision, too coarse beyond it.
NumberRule Coordinate();
/// A length > 0 m and at most 2·kMaxCoordinate_m (a box, a radius).
NumberRule PositiveLength();

/// A short rendering of a node for "got …": a scalar's text (quoted when the
/// file quoted it), a flat list as [a, b], otherwise "a map", "a list of N items", "nothing".
std::string DescribeNode(const YAML::Node& node);

/// `parent.key`, or `key` at the top level.
std::string JoinPath(const std::string& parent, const std::string& key);

/// The keys of one map, checked against the keys its schema allows.
class MapView {
 public:
  /// The field `key` (which must be one of the schema's keys); absent if not in the file.
  Field operator[](const std::string& key) const;
  /// Whether `key` is in the file.
  bool Has(const std::string& key) const;
  /// The map itself.
  const Field& field() const { return field_; }

 private:
  friend class YamlReader;
  MapView(Field field, std::vector<std::string> schema_keys)
      : field_(std::move(field)), schema_keys_(std::move(schema_keys)) {}
  Field field_;
  std::vector<std::string> schema_keys_;
  std::vector<std::pair<std::string, YAML::Node>> entries_;  // file order, first of duplicates only
};

/// Reads typed values out of one document, collecting problems.
class YamlReader {
 public:
  /// `source` names the file in every message (as the user wrote it).
  explicit YamlReader(std::string source) : source_(std::move(source)) {}

  /// The document root as a field.
  Field Root(const YAML::Node& document) const { return Field{document, "", true}; }
  /// `text` parsed as YAML; text that is not YAML throws InputError naming its line.
  YAML::Node Parse(const std::string& text);

  /// Records "SOURCE:LINE: PATH: message" at the field's line.
  void Fail(const Field& field, const std::string& message);
  /// Records "SOURCE: message" (no line, no key: the whole file).
  void FailFile(const std::string& message);
  /// Records "SOURCE:LINE: message" with a line number counted from 1 (0: none).
  void FailAtLine(int line, const std::string& path, const std::string& message);
  /// Every problem recorded so far, in the order of the file's lines (whole-file
  /// problems first, then by line, ties in the order found).
  std::vector<std::string> Problems() const;
  bool HasProblems() const { return !problems_.empty(); }
  const std::string& source() const { return source_; }

  /// Opens a map (a null value counts as an empty map), reporting unknown and
  /// duplicate keys; `expected` describes it in messages (default: "a map
  /// with keys …"). nullopt, after reporting, when the value is not a map.
  /// An absent field gives an empty view.
  std::optional<MapView> Map(const Field& field, std::vector<std::string> schema_keys,
                             const std::string& expected = "");
  std::optional<MapView> Map(const Field& field, std::initializer_list<const char*> schema_keys,
                             const std::string& expected = "") {
    return Map(field, std::vector<std::string>(schema_keys.begin(), schema_keys.end()), expected);
  }
  /// The items of a list as fields `path[i]` (a null value counts as an empty
  /// list); nullopt, after reporting, when the value is not a list.
  std::optional<std::vector<Field>> List(const Field& field, const std::string& expected);

  /// Reports a missing required key; returns whether it is present.
  bool Require(const Field& field, const std::string& expected);

  /// A number obeying `rule`; nullopt if absent or (after reporting) invalid.
  std::optional<double> Number(const Field& field, const NumberRule& rule = AnyNumber());
  /// A whole number >= 0 (decimal digits only).
  std::optional<std::uint64_t> Count(const Field& field);
  /// true/false (also yes/no, on/off as YAML 1.1 allows).
  std::optional<bool> Bool(const Field& field);
  /// A scalar as text; with `non_empty`, the empty string is reported.
  std::optional<std::string> String(const Field& field, bool non_empty = true);
  /// Exactly `count` numbers, each obeying `element`; `expected` describes the list.
  std::optional<std::vector<double>> Numbers(const Field& field, std::size_t count, const NumberRule& element,
                                             const std::string& expected);
  /// Three numbers [x, y, z], each obeying `element`.
  std::optional<Vec3> Vector3(const Field& field, const NumberRule& element, const std::string& expected);

 private:
  std::string source_;
  std::vector<std::pair<int, std::string>> problems_;  // (line or 0, message)
};

}  // namespace proxsim
