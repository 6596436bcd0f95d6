#pragma once
// A real redis-server for a test or a benchmark: started from PATH on a free
// loopback port, with no persistence (--save "" --appendonly no) in a
// directory of its own, and killed and reaped at the end (or when the test
// dies: it shares the test's process group, and a parent-death signal kills
// it if the thread that started it ends first). It can be killed, stopped,
// started again on the same port, paused and resumed, for the tests of what
// a node does when Redis goes away.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fw::test {

class RedisProcess {
 public:
  /// Starts redis-server; ok() says whether it answers PING, error() why not.
  RedisProcess() {
    binary_ = find_in_path("redis-server");
    if (binary_.empty()) {
      error_ = "redis-server is not on PATH: install redis-server (deploy/install-deps.sh)";
      return;
    }
    std::error_code no_temp;
    std::string pattern = (std::filesystem::temp_directory_path(no_temp) / "fw-redis-XXXXXX").string();
    const char* made = no_temp ? nullptr : ::mkdtemp(pattern.data());
    if (made == nullptr) {
      error_ = "cannot make a temporary directory for redis-server";
      return;
    }
    directory_ = made;
    // A free port can be taken between asking and binding: try a few.
    for (int attempt = 0; attempt < 5 && pid_ <= 0; ++attempt) {
      port_ = free_loopback_port();
      if (port_ == 0) continue;
      if (!start()) port_ = 0;
    }
    if (pid_ <= 0 && error_.empty()) error_ = "redis-server did not start";
  }
  ~RedisProcess() {
    kill();
    if (!directory_.empty()) {
      std::error_code ignored;
      std::filesystem::remove_all(directory_, ignored);
    }
  }
  RedisProcess(const RedisProcess&) = delete;
  RedisProcess& operator=(const RedisProcess&) = delete;

  bool ok() const { return pid_ > 0 && error_.empty(); }
  const std::string& error() const { return error_; }
  int port() const { return port_; }
  /// "redis://127.0.0.1:PORT" (db 0).
  std::string url() const { return "redis://127.0.0.1:" + std::to_string(port_); }
  /// The running server's process id, or -1.
  pid_t pid() const { return pid_; }

  /// Starts redis-server (again) on port(), and waits up to 10 s until it
  /// answers PING; false and error() if it does not.
  bool start() {
    if (pid_ > 0) return true;
    error_.clear();
    const std::string port = std::to_string(port_);
    const std::string log = directory_ + "/redis.log";
    std::vector<std::string> args{binary_,  "--port", port,         "--bind",     "127.0.0.1", "--save", "",
                                  "--appendonly", "no",     "--dir",      directory_, "--logfile", log,
                                  "--daemonize",  "no",     "--loglevel", "warning"};
    std::vector<char*> argv;  // made before fork: the child of a threaded test only execs
    for (auto& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
      error_ = "cannot fork for redis-server";
      return false;
    }
    if (pid == 0) {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(127);
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    pid_ = pid;
    paused_ = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (std::chrono::steady_clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        error_ = "redis-server exited at start (port " + port + " taken?): " + log_tail();
        return false;
      }
      if (answers_ping()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    error_ = "redis-server on port " + port + " did not answer PING within 10 s: " + log_tail();
    kill();
    return false;
  }

  /// SIGKILL, as a crash would: no goodbye to its clients' sockets beyond
  /// the kernel's resets.
  void kill() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
    paused_ = false;
  }
  /// SIGTERM and wait (SIGKILL after 10 s): Redis closes its clients.
  void stop() {
    if (pid_ <= 0) return;
    if (paused_) resume();
    ::kill(pid_, SIGTERM);
    for (int waited = 0; waited < 1000; ++waited) {
      if (::waitpid(pid_, nullptr, WNOHANG) == pid_) {
        pid_ = -1;
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    kill();
  }
  /// SIGSTOP: connections stay open and nothing is answered.
  void pause() {
    if (pid_ > 0 && ::kill(pid_, SIGSTOP) == 0) paused_ = true;
  }
  /// SIGCONT.
  void resume() {
    if (pid_ > 0 && ::kill(pid_, SIGCONT) == 0) paused_ = false;
  }

  /// CPU seconds (user + system) the running server has used, for benchmarks; -1 if unknown.
  double cpu_seconds() const {
    std::ifstream stat("/proc/" + std::to_string(pid_) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const auto close = text.rfind(')');
    if (pid_ <= 0 || close == std::string::npos) return -1;
    std::istringstream fields(text.substr(close + 2));
    std::string field;
    unsigned long long utime = 0, stime = 0;
    for (int index = 3; fields >> field; ++index) {  // field 3 is the state
      if (index == 14) utime = std::stoull(field);
      if (index == 15) {
        stime = std::stoull(field);
        break;
      }
    }
    return static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
  }

 private:
  static std::string find_in_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream directories(path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin");
    std::string directory;
    while (std::getline(directories, directory, ':')) {
      const std::string candidate = (directory.empty() ? "." : directory) + "/" + name;
      if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
  }

  static int free_loopback_port() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return 0;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    int port = 0;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
      port = ntohs(address.sin_port);
    ::close(fd);
    return port;
  }

  // A blocking PING over a fresh socket, bounded to half a second.
  bool answers_ping() const {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return false;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(static_cast<std::uint16_t>(port_));
    timeval timeout{0, 500000};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
    bool answered = false;
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
        ::send(fd, "PING\r\n", 6, MSG_NOSIGNAL) == 6) {
      char reply[16] = {};
      const auto got = ::recv(fd, reply, sizeof reply - 1, 0);
      answered = got >= 5 && std::string(reply, 5) == "+PONG";
    }
    ::close(fd);
    return answered;
  }

  std::string log_tail() const {
    std::ifstream log(directory_ + "/redis.log");
    std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    if (text.size() > 600) text = text.substr(text.size() - 600);
    return text.empty() ? "(its log is empty)" : text;
  }

  std::string binary_;
  std::string directory_;
  std::string error_;
  int port_ = 0;
  pid_t pid_ = -1;
  bool paused_ = false;
};

}  // namespace fw::test
