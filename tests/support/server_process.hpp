#pragma once
// Starts a real facewire-server on a free loopback port for a test, and stops
// it at the end (or when the test dies). The server prints its URL on the
// first line of stdout.
#include <csignal>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <poll.h>
#include <sys/prctl.h>

namespace fw::test {

class ServerProcess {
 public:
  /// Starts `binary serve --http 127.0.0.1:0 extra_args...`; port() is 0 if it failed.
  explicit ServerProcess(const std::string& binary, const std::string& extra_args = "") {
    int out[2];
    if (::pipe(out) != 0) return;
    const pid_t parent = ::getpid();
    pid_ = ::fork();
    if (pid_ == 0) {
      // Dies with the test, even when ctest kills the test on its time-out.
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(127);
      ::dup2(out[1], 1);
      ::close(out[0]);
      ::close(out[1]);
      const std::string command = "exec " + binary + " serve --http 127.0.0.1:0 " + extra_args;
      ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(out[1]);
    stdout_fd_ = out[0];
    // Generous: a loaded machine (CI runs tests side by side) may take
    // seconds to make the demo faces and write them to disk.
    const std::string line = read_line(30000);
    const auto colon = line.rfind(':');
    if (colon != std::string::npos) port_ = std::atoi(line.c_str() + colon + 1);
  }
  ~ServerProcess() {
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    if (stdout_fd_ >= 0) ::close(stdout_fd_);
  }
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  int port() const { return port_; }
  /// The server's process id (the shell execs it), e.g. to read /proc/PID.
  pid_t pid() const { return pid_; }

  /// The next line the server prints on stdout (e.g. its TCP address), or
  /// "" after `timeout_ms`.
  std::string next_stdout_line(int timeout_ms) { return read_line(timeout_ms); }

  /// Sends SIGTERM and waits up to `timeout_ms`; the exit status, or -1.
  int terminate(int timeout_ms) {
    ::kill(pid_, SIGTERM);
    for (int waited = 0; waited < timeout_ms; waited += 10) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      ::usleep(10000);
    }
    return -1;
  }

 private:
  std::string read_line(int timeout_ms) {
    std::string line;
    char c;
    pollfd p{stdout_fd_, POLLIN, 0};
    while (::poll(&p, 1, timeout_ms) > 0 && ::read(stdout_fd_, &c, 1) == 1 && c != '\n') line += c;
    return line;
  }

  pid_t pid_ = -1;
  int stdout_fd_ = -1;
  int port_ = 0;
  bool exited_ = false;
};

}  // namespace fw::test
