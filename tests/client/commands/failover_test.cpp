// facewire-client given several servers, against real facewire-server
// processes on loopback: it joins the first that answers, and when its
// server is killed (SIGKILL) it is back in the room on the next within a
// few seconds, under its name; a server that lacks its face gets it
// uploaded again. Servers that share one --data directory share the server
// key and the stored avatars, as the nodes of a cluster do.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <sstream>
#include <thread>

#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "http_get.hpp"
#include "run_command.hpp"
#include "server_process.hpp"

namespace fw::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

fs::path fresh_directory(const std::string& name) {
  static int counter = 0;
  const auto path =
      fs::temp_directory_path() / ("fw-failover-" + name + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(path);
  fs::create_directories(path);
  return path;
}

// A loopback port nobody listens on: bound, then closed (connections to it are refused).
int dead_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t size = sizeof address;
  ::bind(fd, reinterpret_cast<sockaddr*>(&address), size);
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
  ::close(fd);
  return ntohs(address.sin_port);
}

// One facewire-server with the --data directory it is given.
class Node {
 public:
  explicit Node(const fs::path& data)
      : process_(std::make_unique<ServerProcess>(
            bin("facewire-server"), "--data " + data.string() +
                                        " --no-demo-room --log-level warn --joins-per-minute 100000"
                                        " --room-joins-per-minute 100000 --rooms-per-hour 100000 --seats-per-address 64"
                                        " --rooms-per-address 100000 --rooms-per-block 100000 --seats-per-block 64")) {}
  int port() const { return port_; }
  std::string url() const { return "ws://127.0.0.1:" + std::to_string(port_) + "/"; }
  /// kill -9, as a node that dies.
  void kill() { process_.reset(); }
  /// How many avatars room `room` holds now (0 when the server does not answer).
  int avatars_in(const std::string& room) const {
    const auto json = nlohmann::json::parse(http_get(port_, "/api/rooms").body, nullptr, false);
    if (json.is_object() && json.contains("rooms"))
      for (const auto& entry : json["rooms"])
        if (entry.value("name", "") == room) return entry.value("avatars", 0);
    return 0;
  }
  /// Waits until room `room` holds `count` avatars; the seconds it took, or -1.
  double wait_for(const std::string& room, int count, double timeout_s) const {
    const auto start = Clock::now();
    while (Clock::now() - start < std::chrono::duration<double>(timeout_s)) {
      if (avatars_in(room) >= count) return std::chrono::duration<double>(Clock::now() - start).count();
      std::this_thread::sleep_for(100ms);
    }
    return -1;
  }

 private:
  std::unique_ptr<ServerProcess> process_;
  int port_ = process_->port();
};

// `facewire-client join ARGS --json` in the background, until stop() (or
// its --seconds); its stderr (the events: where it moved and why) kept in a
// file.
class Client {
 public:
  Client(const std::string& name, const std::string& args)
      : log_(fs::temp_directory_path() / ("fw-failover-client-" + name + "-" + std::to_string(::getpid()) + ".log")) {
    const std::string command =
        "exec " + bin("facewire-client") + " join " + args + " --name " + name + " --seconds 90 --json -q 2>" + log_.string();
    int fd = -1;
    pid_ = spawn_shell(command, false, fd);
    output_ = std::async(std::launch::async, [fd] {
      std::string text;
      char buffer[4096];
      for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
      ::close(fd);
      return text;
    });
  }
  ~Client() {
    stop();
    fs::remove(log_);
  }
  /// Ends the client as Ctrl-C would (it prints its summary), and waits for it.
  void stop() {
    if (stopped_ || pid_ <= 0) return;
    stopped_ = true;
    ::kill(pid_, SIGTERM);
    const std::string output = output_.get();
    int raw = 0;
    while (::waitpid(pid_, &raw, 0) < 0 && errno == EINTR) {
    }
    status_ = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
      if (auto json = nlohmann::json::parse(line, nullptr, false); json.is_object()) summary_ = json;
  }
  int status() {
    stop();
    return status_;
  }
  const nlohmann::json& summary() {
    stop();
    return summary_;
  }
  std::string log() const {
    std::ifstream in(log_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  bool logged(const std::string& part) const { return log().find(part) != std::string::npos; }
  /// Waits until the client said `part` (e.g. that it joined), at most `timeout_s`.
  bool wait_to_log(const std::string& part, double timeout_s) const {
    const auto start = Clock::now();
    while (!logged(part)) {
      if (Clock::now() - start > std::chrono::duration<double>(timeout_s)) return false;
      std::this_thread::sleep_for(100ms);
    }
    std::this_thread::sleep_for(500ms);  // its render loop, which decides the exit status, sees it too
    return true;
  }

 private:
  fs::path log_;
  pid_t pid_ = -1;
  std::future<std::string> output_;
  int status_ = -1;
  nlohmann::json summary_ = nlohmann::json::object();
  bool stopped_ = false;
};

// Whether `summary`'s events have `kind` for `name`.
bool has_event(const nlohmann::json& summary, const std::string& kind, const std::string& name) {
  for (const auto& event : summary.value("events", nlohmann::json::array()))
    if (event.value("kind", "") == kind && event.value("name", "") == name) return true;
  return false;
}

TEST(Failover, JoinsTheFirstServerOfTheListThatAnswers) {
  const fs::path data = fresh_directory("data");
  Node b(data);
  ASSERT_GT(b.port(), 0);
  const std::string dead = "ws://127.0.0.1:" + std::to_string(dead_port()) + "/";
  Client ada("ada", dead + "," + b.url() + " --room hall");
  EXPECT_TRUE(ada.wait_to_log("joined room hall as avatar 1 with 1 avatar(s) present on " + b.url(), 20)) << ada.log();
  EXPECT_EQ(b.avatars_in("hall"), 1);
  EXPECT_EQ(ada.status(), 0) << ada.log();
  EXPECT_EQ(ada.summary().value("server", ""), b.url()) << ada.log();
  EXPECT_TRUE(ada.logged("cannot connect: ")) << ada.log();
  EXPECT_TRUE(ada.logged("moving to " + b.url() + " (server 2 of 2)")) << ada.log();
  fs::remove_all(data);
}

TEST(Failover, AKilledServersClientIsBackInTheRoomOnTheNextUnderItsName) {
  const fs::path data = fresh_directory("data");  // shared: a cluster's key and avatars
  Node a(data), b(data);
  ASSERT_GT(a.port(), 0);
  ASSERT_GT(b.port(), 0);
  // Bob watches the room on B; Ada joins A, the first of her list.
  Client bob("bob", b.url() + " --room hall");
  ASSERT_GE(b.wait_for("hall", 1, 20), 0) << bob.log();
  Client ada("ada", a.url() + "," + b.url() + " --room hall");
  ASSERT_TRUE(ada.wait_to_log("present on " + a.url(), 20)) << ada.log();

  a.kill();
  const double back_s = b.wait_for("hall", 2, 30);
  ASSERT_GE(back_s, 0) << "ada never reached B\n" << ada.log();
  std::printf("back in the room on B %.2f s after A was killed\n", back_s);
  EXPECT_LT(back_s, 10.0) << ada.log();
  EXPECT_TRUE(ada.logged("moving to " + b.url() + " (server 2 of 2)")) << ada.log();
  EXPECT_TRUE(ada.wait_to_log("present on " + b.url(), 10)) << ada.log();

  EXPECT_EQ(ada.status(), 0) << ada.log();
  EXPECT_EQ(bob.status(), 0) << bob.log();
  EXPECT_TRUE(has_event(bob.summary(), "joined", "ada")) << "bob saw her arrive under her name\n" << bob.summary().dump();
  EXPECT_EQ(ada.summary().value("server", ""), b.url());
  EXPECT_EQ(ada.summary().value("reconnects", 0), 1);
  fs::remove_all(data);
}

TEST(Failover, AServerThatLacksTheFaceGetsItUploadedAgain) {
  const fs::path data_a = fresh_directory("a"), data_b = fresh_directory("b");  // two servers that share nothing
  Node a(data_a), b(data_b);
  ASSERT_GT(a.port(), 0);
  ASSERT_GT(b.port(), 0);
  Client ada("ada", a.url() + "," + b.url() + " --room hall --photo " + test_photo("astronaut.png"));
  ASSERT_TRUE(ada.wait_to_log("present on " + a.url(), 40)) << ada.log();
  a.kill();
  const double back_s = b.wait_for("hall", 1, 40);
  ASSERT_GE(back_s, 0) << "ada never reached B\n" << ada.log();
  std::printf("back in the room on B %.2f s after A was killed, the photo uploaded and prepared again\n", back_s);
  EXPECT_TRUE(ada.logged(b.url() + " refused the face (unknown avatar")) << ada.log();
  EXPECT_TRUE(ada.logged("uploaded the face to " + b.url())) << ada.log();
  EXPECT_TRUE(ada.wait_to_log("present on " + b.url(), 10)) << ada.log();
  EXPECT_EQ(ada.status(), 0) << ada.log();
  EXPECT_EQ(ada.summary().value("server", ""), b.url());
  // B stored the face it was given.
  EXPECT_TRUE(fs::exists(data_b / "avatars") && !fs::is_empty(data_b / "avatars")) << "nothing stored on B";
  fs::remove_all(data_a);
  fs::remove_all(data_b);
}

}  // namespace
}  // namespace fw::test
