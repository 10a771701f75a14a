// Input files are regular files of a bounded size (issue 23, issue 40): a
// FIFO blocks its reader for ever, /dev/zero is read until memory runs out.
#pragma once

#include <string>

namespace proxsim {

/// Why `path` is not a readable input file (missing, not regular, larger than
/// `max_bytes`); empty when it is one. Uses stat(), never open(): opening a
/// FIFO blocks.
std::string RegularFileProblem(const std::string& path, unsigned long long max_bytes);

}  // namespace proxsim
