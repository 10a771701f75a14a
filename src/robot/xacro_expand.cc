// ExpandXacro: `xacro FILE` in a child process (posix_spawn, no shell: a path
// is passed as it is), its standard output read as the URDF, its standard
// error kept for the message when it fails.
#include "robot/xacro_expand.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/input_limits.h"

extern char** environ;

namespace proxsim {

std::string XacroExecutable() {
  if (const char* chosen = std::getenv("PROXSIM_XACRO"); chosen != nullptr && chosen[0] != '\0') return chosen;
#ifdef PROXSIM_XACRO_DEFAULT
  if (::access(PROXSIM_XACRO_DEFAULT, X_OK) == 0) return PROXSIM_XACRO_DEFAULT;
#endif
  return "xacro";
}

namespace {

// everything a descriptor gives until its end, at most `limit` bytes kept
std::string ReadAll(int fd, std::size_t limit) {
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (text.size() < limit) text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace

std::string ExpandXacro(const std::string& path) {
  const std::string xacro = XacroExecutable();
  const std::string run = "`" + xacro + " " + path + "`";
  // stdout to one pipe; stderr to a temporary file (read after the exit: two
  // pipes read one after the other could block on a chatty child)
  int out[2];
  if (::pipe(out) != 0) throw InputError(path + ": this is xacro, and " + run + " could not start: no pipe");
  char err_path[] = "/tmp/proxsim-xacro-XXXXXX";
  const int err = ::mkstemp(err_path);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
  if (err >= 0) posix_spawn_file_actions_adddup2(&actions, err, STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, out[0]);
  std::vector<char*> argv = {const_cast<char*>(xacro.c_str()), const_cast<char*>(path.c_str()), nullptr};
  pid_t child = -1;
  const int spawned = ::posix_spawnp(&child, xacro.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  std::string urdf, message;
  int status = 0;
  if (spawned == 0) {
    urdf = ReadAll(out[0], kMaxUrdfBytes + 1);
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
  }
  ::close(out[0]);
  if (err >= 0) {
    ::lseek(err, 0, SEEK_SET);
    message = ReadAll(err, 4096);
    ::close(err);
    ::unlink(err_path);
  }
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  if (spawned != 0) {
    throw InputError(path + ": this is xacro, and " + run + " could not start (" + std::strerror(spawned) +
                     "): run scripts/install-deps.sh (it installs xacro into .venv/), or set PROXSIM_XACRO");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw InputError(path + ": " + run + " failed" +
                     (WIFEXITED(status) ? " (exit " + std::to_string(WEXITSTATUS(status)) + ")" : std::string()) +
                     (message.empty() ? std::string() : ": " + message));
  }
  return urdf;
}

}  // namespace proxsim
