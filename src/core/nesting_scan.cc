#include "core/nesting_scan.h"

#include <cctype>
#include <vector>

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

NestingScan ScanYamlNesting(std::string_view text, int limit) {
  NestingScan scan;
  std::vector<std::size_t> block;  // the indentation columns of the open block levels
  int flow = 0;
  char quote = 0;
  bool line_start = true;
  const auto deeper = [&](std::size_t at) {
    const int depth = static_cast<int>(block.size()) + flow;
    ++scan.elements;
    if (depth > scan.max_depth) scan.max_depth = depth;
    if (depth > limit) scan.too_deep_at = at == 0 ? 1 : at;
    return depth > limit;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool block_line = line_start && quote == 0 && flow == 0;
    line_start = false;
    if (block_line) {
      // a block line: its indentation (and each "- " on it) opens levels deeper than the last
      std::size_t column = 0;
      while (i + column < text.size() && text[i + column] == ' ') ++column;
      const char first = i + column < text.size() ? text[i + column] : '\n';
      if (first == '\n' || first == '\r' || first == '#') {
        i += column - 1;  // the loop's ++i lands on the line end or the comment
        continue;
      }
      while (!block.empty() && block.back() >= column) block.pop_back();
      block.push_back(column);
      if (deeper(i + column)) return scan;
      while (i + column + 1 < text.size() && text[i + column] == '-' && text[i + column + 1] == ' ') {
        column += 2;
        while (i + column < text.size() && text[i + column] == ' ') ++column;
        block.push_back(column);
        if (deeper(i + column)) return scan;
      }
      i += column;
      if (i >= text.size()) break;
    }
    const char c = text[i];
    if (c == '\n') {
      line_start = true;  // (a quoted scalar may span lines: its next line is no block line)
      continue;
    }
    if (quote != 0) {
      if (quote == '"' && c == '\\') ++i;
      else if (c == quote) quote = 0;
      continue;
    }
    if (c == '#' && (i == 0 || text[i - 1] == ' ' || text[i - 1] == '\t' || text[i - 1] == '\n')) {
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;  // a comment, to the line's end
    } else if (c == '"' || (c == '\'' && (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1]))))) {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++flow;
      if (deeper(i)) return scan;
    } else if ((c == ']' || c == '}') && flow > 0) {
      --flow;
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
