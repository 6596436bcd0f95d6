#pragma once
// The client sessions open on this server, so that a drain can tell each
// to leave and knows when all have. Apart from the rooms (room_registry.hpp):
// a session exists before it chose a room, and a room outlives none of it.
// Thread-safe.
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>

namespace fw::server {

class ClientSession;

class SessionRegistry {
 public:
  void add(const std::shared_ptr<ClientSession>& session);
  void remove(const ClientSession* session);
  std::size_t count() const;
  /// Tells every open session that the server shuts down.
  void close_all();

 private:
  mutable std::mutex mutex_;
  std::map<const ClientSession*, std::weak_ptr<ClientSession>> sessions_;
};

}  // namespace fw::server
