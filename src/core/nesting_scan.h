// Pre-scans of XML and JSON text for how deep its elements nest and how many
// there are, without building anything: a few counters over the bytes, no
// recursion. Run before a recursive parser (TinyXML, pugixml, rapidjson) gets
// the text, so that a file nested 200 000 deep is an input error, not a stack
// overflow.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace proxsim {

struct NestingScan {
  int max_depth = 0;          ///< deepest nesting seen (stops counting past the limit)
  std::size_t elements = 0;   ///< XML elements, or JSON arrays and objects
  std::size_t too_deep_at = 0;  ///< byte offset where the limit was first passed; 0 when it never was
};

/// XML: elements opened and not yet closed; comments, CDATA, processing
/// instructions, DOCTYPE and quoted attribute values are skipped.
NestingScan ScanXmlNesting(std::string_view text, int limit);

/// JSON: '[' and '{' outside strings (escapes honoured).
NestingScan ScanJsonNesting(std::string_view text, int limit);

/// YAML: flow collections ('[' and '{' outside quotes and comments) inside
/// block ones (a stack of indentation columns, each "- " a level of its
/// own), counted together. yaml-cpp recurses per level and answers a file
/// 600 maps deep with "bad file", naming nothing.
NestingScan ScanYamlNesting(std::string_view text, int limit);

/// "PATH: <what> nested deeper than LIMIT levels (at byte N); ..." when the
/// scan passed the limit, nullopt otherwise.
std::optional<std::string> NestingProblem(const NestingScan& scan, const std::string& path, const std::string& what,
                                          int limit);

}  // namespace proxsim
