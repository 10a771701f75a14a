// Runs a program that ships with proxsim's toolchain (Debian's python3 for the
// report, node for the MCAP exporter) as a child process: posix_spawn, no
// shell (arguments pass as they are), waited for through interruptions.
#pragma once

#include <string>
#include <vector>

namespace proxsim {

/// Runs `args` (args[0] is `program`'s name as it sees it) and returns its exit
/// status; 1 when it cannot start or is killed by a signal, saying why on stderr
/// (`what` names it there: "the report script").
int RunChildProcess(const std::string& program, std::vector<std::string> args, const std::string& what);

}  // namespace proxsim
