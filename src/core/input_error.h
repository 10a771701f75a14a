// The one channel for bad user input: every problem found is collected, then
// thrown together so the user fixes them all in one go. The CLI turns it into
// exit code 2. Our own bugs are asserts, never InputError.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace proxsim {

/// Bad input (scenario, URDF, mesh, trajectory, command line): one message per
/// problem, each naming the file, the line where there is one, the key and what
/// was expected.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<std::string> problems);
  explicit InputError(std::string problem) : InputError(std::vector<std::string>{std::move(problem)}) {}
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

}  // namespace proxsim
