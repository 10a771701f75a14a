// Running other processes from `proxsim bench`: a command's output, and a
// command's wall time (for the sections that time the CLI, Python or mpirun).
#pragma once

#include <string>

namespace proxsim::bench {

/// Runs a command through the shell and returns its standard output ("" when it failed).
std::string Capture(const std::string& command);

/// Runs a command through the shell, output discarded; its wall time in
/// seconds, or a negative value when it did not exit with 0.
double TimeCommand_s(const std::string& command);

/// This executable's own path (/proc/self/exe), to run `proxsim` subcommands.
std::string SelfExecutable();

}  // namespace proxsim::bench
