#include "core/input_error.h"

namespace proxsim {

namespace {
std::string JoinLines(const std::vector<std::string>& lines) {
  std::string all;
  for (const auto& line : lines) {
    if (!all.empty()) all += '\n';
    all += line;
  }
  return all;
}
}  // namespace

InputError::InputError(std::vector<std::string> problems)
    : std::runtime_error(JoinLines(problems)), problems_(std::move(problems)) {}

}  // namespace proxsim
