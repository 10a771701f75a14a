// For tests of bad input: the message an action throws.
#pragma once

#include <string>

#include "core/input_error.h"

namespace proxsim::testing {

/// The message of the InputError thrown by `f`, or "" when nothing is thrown.
template <typename F>
std::string ErrorOf(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace proxsim::testing
