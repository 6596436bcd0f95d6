#include "session_registry.hpp"

#include <vector>

#include "client_session.hpp"

namespace fw::server {

void SessionRegistry::add(const std::shared_ptr<ClientSession>& session) {
  std::lock_guard lock(mutex_);
  sessions_.emplace(session.get(), session);
}

void SessionRegistry::remove(const ClientSession* session) {
  std::lock_guard lock(mutex_);
  sessions_.erase(session);
}

std::size_t SessionRegistry::count() const {
  std::lock_guard lock(mutex_);
  return sessions_.size();
}

void SessionRegistry::close_all() {
  // Closed outside the lock: a session that closes removes itself.
  std::vector<std::shared_ptr<ClientSession>> open;
  {
    std::lock_guard lock(mutex_);
    for (auto& [key, weak] : sessions_)
      if (auto session = weak.lock()) open.push_back(std::move(session));
  }
  for (auto& session : open)
    session->close(codec::CloseCode::shutting_down, "the server is shutting down; reconnect in a moment");
}

}  // namespace fw::server
