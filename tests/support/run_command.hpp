#pragma once
// Runs a facewire executable as a person would and captures what it says.
// A program that hangs is killed when its time-out runs out, and it dies with
// the test process if ctest kills the test, so that no test can block CI.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <string>

#include "test_paths.hpp"

namespace fw::test {

struct CommandResult {
  int status = -1;         ///< exit status, or -1 if it did not exit normally
  std::string output;      ///< stdout, and stderr unless left out
  bool timed_out = false;  ///< killed after its time-out
};

/// Starts `command_line` under /bin/sh in a process group of its own that is
/// killed (SIGKILL) if the calling process dies first. Its stdout (and
/// stderr, if `with_stderr`) goes to the returned pipe; -1 on failure.
inline pid_t spawn_shell(const std::string& command_line, bool with_stderr, int& read_fd) {
  int out[2];
  if (::pipe(out) != 0) return -1;
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the test died before prctl took hold
    ::dup2(out[1], 1);
    if (with_stderr) ::dup2(out[1], 2);
    ::close(out[0]);
    ::close(out[1]);
    ::execl("/bin/sh", "sh", "-c", command_line.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(out[1]);
  if (pid < 0) {
    ::close(out[0]);
    return -1;
  }
  read_fd = out[0];
  return pid;
}

/// Runs `command_line` through the shell, capturing stdout and, if
/// `with_stderr`, stderr interleaved with it (otherwise stderr goes to the
/// test's own, where ctest shows it on failure). After `timeout_s` seconds
/// the command and everything it started are killed and `timed_out` is set.
inline CommandResult run_command(const std::string& command_line, bool with_stderr = true, int timeout_s = 50) {
  CommandResult result;
  int fd = -1;
  const pid_t pid = spawn_shell(command_line, with_stderr, fd);
  if (pid < 0) return result;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  std::array<char, 4096> buffer;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      result.timed_out = true;
      break;
    }
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n <= 0) break;  // EOF: the command closed its output
    result.output.append(buffer.data(), static_cast<std::size_t>(n));
  }
  ::close(fd);
  if (result.timed_out) {
    ::kill(-pid, SIGKILL);
    result.output += "\n[run_command: killed after " + std::to_string(timeout_s) + " s: " + command_line + "]\n";
  }
  int raw = 0;
  while (::waitpid(pid, &raw, 0) < 0 && errno == EINTR) {
  }
  if (!result.timed_out && WIFEXITED(raw)) result.status = WEXITSTATUS(raw);
  return result;
}

}  // namespace fw::test
