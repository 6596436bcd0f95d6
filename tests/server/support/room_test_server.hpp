#pragma once
// A facewire-server for the room tests: started on free loopback ports (HTTP
// and TCP) with its own data directory, and a client joined to a room.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "room_test_client.hpp"
#include "run_command.hpp"
#include "server_process.hpp"

namespace fw::test {

using namespace std::chrono_literals;
using Transport = RoomTestClient::Transport;

/// Flags that raise what one address may do (joins, chat, new rooms, seats
/// in a room), for tests that run many clients from 127.0.0.1 to test
/// something else; the limits' own tests (address_rate_limits_test.cpp)
/// keep the defaults.
inline const std::string kManyClientsFromOneAddress =
    " --joins-per-minute 100000 --chat-per-minute 100000 --room-chat-per-minute 100000 --room-joins-per-minute 100000 --rooms-per-hour 100000"
    " --seats-per-address 64 --seats-per-block 64 --rooms-per-address 100000 --rooms-per-block 100000 ";

/// A server with a TCP port and its own data directory.
class RunningServer {
 public:
  explicit RunningServer(const std::string& extra_args = "")
      : data_(std::filesystem::temp_directory_path() / ("fw-room-test-" + std::to_string(::getpid()) + "-" +
                                                         std::to_string(counter_++))),
        process_(bin("facewire-server"),
                 "--tcp 127.0.0.1:0 --data " + data_.string() + " " + extra_args) {
    const std::string line = process_.next_stdout_line(30000);
    const auto colon = line.rfind(':');
    if (colon != std::string::npos) tcp_port_ = std::atoi(line.c_str() + colon + 1);
  }
  ~RunningServer() { std::filesystem::remove_all(data_); }
  int http_port() const { return process_.port(); }
  /// Its --data directory (the avatar store is DIR/avatars).
  const std::filesystem::path& data() const { return data_; }
  int tcp_port() const { return tcp_port_; }
  int port(Transport t) const { return t == Transport::tcp ? tcp_port_ : http_port(); }
  ServerProcess& process() { return process_; }
  /// Resident memory of the server process, kB.
  long rss_kb() const {
    std::ifstream status("/proc/" + std::to_string(process_.pid()) + "/status");
    std::string key;
    long value = 0;
    while (status >> key)
      if (key == "VmRSS:" && status >> value) return value;
    return -1;
  }

 private:
  static inline int counter_ = 0;
  std::filesystem::path data_;
  ServerProcess process_;
  int tcp_port_ = 0;
};

inline std::unique_ptr<RoomTestClient> join(const RunningServer& server, Transport transport, const std::string& room,
                                     const std::string& name, const std::string& token = "",
                                     std::uint32_t max_bps = 0) {
  auto client = std::make_unique<RoomTestClient>(transport, server.port(transport));
  EXPECT_TRUE(client->connected());
  client->hello(room, name, token, max_bps);
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 5s);
  return client;
}

}  // namespace fw::test
