#include "core/text_fields.h"

#include <cstdio>

namespace proxsim {

void AppendCsvField(std::string& line, std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) {
    line += field;
    return;
  }
  line += '"';
  for (const char c : field) {
    if (c == '"') line += '"';
    line += c;
  }
  line += '"';
}

std::string CsvField(std::string_view field) {
  std::string text;
  AppendCsvField(text, field);
  return text;
}

std::string NamingProblem(std::string_view name) {
  if (name.empty()) return "an empty name";
  char where[64];
  for (std::size_t i = 0; i < name.size();) {
    const auto byte = static_cast<unsigned char>(name[i]);
    if (byte < 0x20 || byte == 0x7f) {
      std::snprintf(where, sizeof where, "a control character (byte 0x%02x at %zu)", byte, i);
      return where;
    }
    // UTF-8: the sequence length from the lead byte, then continuation bytes
    const std::size_t length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xe ? 3 : (byte >> 3) == 0x1e ? 4 : 0;
    bool valid = length > 0 && i + length <= name.size() && !(length == 2 && byte < 0xc2);
    for (std::size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(name[i + k]) & 0xc0) == 0x80;
    if (!valid) {
      std::snprintf(where, sizeof where, "invalid UTF-8 (byte 0x%02x at %zu)", byte, i);
      return where;
    }
    i += length;
  }
  return "";
}

}  // namespace proxsim
