// Numbers in text outputs: the shortest decimal that reads back to the same
// double (std::to_chars), so files are exact, compact, locale-free and
// byte-identical across runs. NaN is written as an empty field.
#pragma once

#include <charconv>
#include <string>

namespace proxsim {

/// Appends `value` to `out`; appends nothing for NaN.
inline void AppendNumber(std::string& out, double value) {
  if (value != value) return;
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

/// Appends an integer.
inline void AppendInteger(std::string& out, long long value) {
  char buffer[24];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace proxsim
