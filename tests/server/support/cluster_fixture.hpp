#pragma once
// A cluster on loopback for the cluster suites (server/CLUSTER.md): a real
// redis-server the test starts itself, real facewire-server nodes on it,
// and the steps every such test takes (wait for a node to be ready, join a
// room on a node, pump clients while the room goes on).
#include <chrono>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "http_get.hpp"
#include "redis_blocking.hpp"
#include "redis_process.hpp"
#include "room_test_server.hpp"

namespace fw::test {

using namespace std::chrono_literals;

class Cluster {
 public:
  Cluster() { EXPECT_TRUE(redis_.ok()) << redis_.error(); }
  RedisProcess& redis() { return redis_; }

  /// `flags`: the limits this node runs with (by default, many clients from 127.0.0.1).
  RunningServer& add_node(const std::string& name, const std::string& flags = kManyClientsFromOneAddress) {
    nodes_.push_back(
        std::make_unique<RunningServer>("--redis " + redis_.url() + " --node " + name + " --rejoin-grace 60 " + flags));
    names_.push_back(name);
    return *nodes_.back();
  }
  RunningServer& node(std::size_t i) { return *nodes_.at(i); }
  std::size_t index_of(const std::string& name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return i;
    return names_.size();
  }

  /// The node that owns `room` now, by Redis; empty if none.
  std::string owner_of(const std::string& room) {
    server::RedisBlocking redis(redis_address(), 2000ms);
    const auto reply = redis.command({"GET", "fw:room:" + room + ":owner"});
    return reply && reply->type == server::RedisReply::Type::string ? reply->text : "";
  }
  server::RedisAddress redis_address() const {
    server::RedisAddress address;
    address.host = "127.0.0.1";
    address.port = static_cast<std::uint16_t>(redis_.port());
    return address;
  }

 private:
  RedisProcess redis_;
  std::vector<std::unique_ptr<RunningServer>> nodes_;
  std::vector<std::string> names_;
};

inline bool ready(int http_port) { return http_get(http_port, "/readyz").status == 200; }

template <class Predicate>
bool eventually(Predicate done, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(50ms);
  }
  return done();
}

/// The avatars a client knows are in its room: the welcome's, then presence.
inline std::set<std::uint32_t> known_avatars(const RoomTestClient& client) {
  std::set<std::uint32_t> ids;
  if (!client.welcome) return ids;
  for (const auto& info : client.welcome->avatars) ids.insert(info.id);
  for (const auto& p : client.presence) {
    if (p.change == codec::Presence::Change::joined) ids.insert(p.avatar.id);
    else ids.erase(p.avatar.id);
  }
  return ids;
}

inline std::unique_ptr<RoomTestClient> join_node(RunningServer& node, const std::string& room, const std::string& name,
                                          const std::string& resume = "", const std::string& from = "",
                                          const std::string& language = "") {
  auto client = std::make_unique<RoomTestClient>(RoomTestClient::Transport::websocket, node.http_port(), from);
  EXPECT_TRUE(client->connected());
  codec::Hello hello;
  hello.room = room;
  hello.name = name;
  hello.resume = resume;
  hello.language = language;
  hello.timestamps = true;  // the tick of each frame, for the pace
  client->send_message(hello);
  EXPECT_TRUE(client->pump_until([&] { return client->welcome.has_value() || client->closed(); }, 15s))
      << name << " had no welcome";
  EXPECT_TRUE(client->welcome.has_value()) << name << ": "
                                           << (client->closing ? client->closing->reason : std::string("no closing"));
  return client;
}

/// Pumps every client for `duration`.
inline void pump_all(const std::vector<RoomTestClient*>& clients, std::chrono::milliseconds duration) {
  const auto end = std::chrono::steady_clock::now() + duration;
  while (std::chrono::steady_clock::now() < end)
    for (RoomTestClient* c : clients) c->pump_for(20ms);
}

}  // namespace fw::test
