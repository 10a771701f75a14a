#include "report/child_process.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstring>
#include <iostream>

extern char** environ;

namespace proxsim {

int RunChildProcess(const std::string& program, std::vector<std::string> args, const std::string& what) {
  // spawn it, no shell: arguments pass as they are
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawn_error = posix_spawn(&pid, program.c_str(), nullptr, nullptr, argv.data(), environ);
  if (spawn_error != 0) {
    std::cerr << "proxsim: cannot start " << program << ": " << std::strerror(spawn_error) << "\n";
    return 1;
  }

  // wait for it, through interruptions
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      std::cerr << "proxsim: lost " << what << ": " << std::strerror(errno) << "\n";
      return 1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  std::cerr << "proxsim: " << what << " was killed by signal " << WTERMSIG(status) << "\n";
  return 1;
}

}  // namespace proxsim
