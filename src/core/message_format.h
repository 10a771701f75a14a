// Numbers in messages and events for a person (a printf format with up to
// four numbers): "at (2.40, -0.13) m". Files use core/number_format.h instead.
#pragma once

#include <cstdio>
#include <string>

namespace proxsim {

/// `format` (printf, up to four %f/%g-style conversions) filled with a, b, c, d.
inline std::string FormatNumbers(const char* format, double a, double b = 0, double c = 0, double d = 0) {
  char text[256];
  std::snprintf(text, sizeof text, format, a, b, c, d);
  return text;
}

}  // namespace proxsim
