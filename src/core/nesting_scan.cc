#include "core/nesting_scan.h"

namespace proxsim {

NestingScan ScanXmlNesting(std::string_view text, int limit) {
  NestingScan scan;
  int depth = 0;
  std::size_t i = 0;
  const auto skip_past = [&](std::string_view end) {
    const std::size_t at = text.find(end, i);
    i = at == std::string_view::npos ? text.size() : at + end.size();
  };
  while (i < text.size()) {
    const std::size_t open = text.find('<', i);
    if (open == std::string_view::npos) break;
    i = open + 1;
    const std::string_view rest = text.substr(i);
    // markup that opens no element
    if (rest.starts_with("!--")) {
      skip_past("-->");
    } else if (rest.starts_with("![CDATA[")) {
      skip_past("]]>");
    } else if (rest.starts_with("?")) {
      skip_past("?>");
    } else if (rest.starts_with("!")) {
      // DOCTYPE, with an internal subset in brackets
      int brackets = 0;
      for (; i < text.size(); ++i) {
        if (text[i] == '[') ++brackets;
        if (text[i] == ']') --brackets;
        if (text[i] == '>' && brackets <= 0) break;
      }
      ++i;
    } else if (rest.starts_with("/")) {
      if (depth > 0) --depth;
      skip_past(">");
    } else {
      // a start tag: to its '>', past quoted attribute values; "/>" closes it at once
      char quote = 0;
      char last = 0;
      for (; i < text.size(); ++i) {
        const char c = text[i];
        if (quote != 0) {
          if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '>') {
          break;
        }
        if (quote == 0 && c != '>' && c != ' ' && c != '\t' && c != '\n' && c != '\r') last = c;
      }
      ++i;
      ++scan.elements;
      if (last == '/') continue;
      ++depth;
      if (depth > scan.max_depth) scan.max_depth = depth;
      if (depth > limit && scan.too_deep_at == 0) {
        scan.too_deep_at = open;
        return scan;
      }
    }
  }
  return scan;
}

NestingScan ScanJsonNesting(std::string_view text, int limit) {
  NestingScan scan;
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;  // the escaped byte is never a quote that ends the string
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      ++scan.elements;
      if (++depth > scan.max_depth) scan.max_depth = depth;
      if (depth > limit) {
        scan.too_deep_at = i == 0 ? 1 : i;
        return scan;
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return scan;
}

std::optional<std::string> NestingProblem(const NestingScan& scan, const std::string& path, const std::string& what,
                                          int limit) {
  if (scan.too_deep_at == 0) return std::nullopt;
  return path + ": " + what + " nested deeper than " + std::to_string(limit) + " levels (at byte " +
         std::to_string(scan.too_deep_at) + "); proxsim refuses such files before parsing them (limit: " +
         std::to_string(limit) + " levels, docs/trust.md)";
}

}  // namespace proxsim
