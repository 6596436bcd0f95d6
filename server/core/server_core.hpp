#pragma once
// Everything a running server holds apart from its sockets: the shared
// context, the avatar store with the demo faces, the worker pool that ticks
// the rooms, and the rooms themselves. `facewire-server serve` puts listeners
// in front of it (network_server.hpp); tests and benchmarks put in-memory
// sessions in front of it (in_memory_session.hpp).
#include <memory>
#include <string>

#include <boost/asio/thread_pool.hpp>

#include "avatar_store.hpp"
#include "room_bus_relay.hpp"
#include "room_registry.hpp"
#include "server_config.hpp"
#include "server_context.hpp"
#include "session_registry.hpp"

namespace fw::server {

class ServerCore {
 public:
  explicit ServerCore(const ServerConfig& config);
  /// Stops the rooms and waits for the worker pool.
  ~ServerCore();
  ServerCore(const ServerCore&) = delete;
  ServerCore& operator=(const ServerCore&) = delete;

  /// Opens the avatar store (config.data) and stores the demo faces, then
  /// makes the rooms' registry; false and `error`, for the person starting
  /// the server, if either fails.
  bool open(std::string& error);
  /// Opens the demo room when the configuration asks for one, and marks the
  /// server ready (/readyz) once its faces are seated.
  void open_demo_room();

  /// No new joins; every open session is told that the server shuts down.
  void start_draining();
  /// Every session has left.
  bool drained() const;
  /// Closes every room and waits until the worker pool has nothing left to do.
  void stop();

  ServerContext& context() { return context_; }
  /// Once open() succeeded.
  RoomRegistry& rooms() { return *rooms_; }
  SessionRegistry& sessions() { return sessions_; }

 private:
  ServerContext context_;
  std::unique_ptr<AvatarStore> store_;
  std::unique_ptr<AddressLimits> addresses_;
  boost::asio::thread_pool workers_;
  RoomBusRelay bus_;
  SessionRegistry sessions_;
  std::unique_ptr<RoomRegistry> rooms_;
  bool stopped_ = false;
};

}  // namespace fw::server
