#include "server_core.hpp"

#include "demo_room.hpp"
#include "server_keys.hpp"

namespace fw::server {

ServerCore::ServerCore(const ServerConfig& config)
    : workers_(static_cast<std::size_t>(config.workers)), rooms_(context_) {
  context_.config = config;
  addresses_ = std::make_unique<AddressLimits>(config.abuse);
  context_.addresses = addresses_.get();
  context_.physics_lod.set_enabled(config.physics && config.physics_lod);
  context_.workers = &workers_;
  context_.rooms = &rooms_;
}

ServerCore::~ServerCore() { stop(); }

bool ServerCore::open(std::string& error) {
  store_ = std::make_unique<AvatarStore>(context_.config.data, context_.metrics, error);
  if (!error.empty()) {
    error += " (choose another directory with --data DIR)";
    return false;
  }
  context_.store = store_.get();
  context_.server_key = load_or_create_server_key(context_.config.data, error);
  if (context_.server_key.empty()) return false;
  return make_demo_avatars(context_, error);
}

void ServerCore::open_demo_room() {
  if (!context_.config.demo_room) {
    context_.ready = true;
    return;
  }
  fw::server::open_demo_room(context_, [this] { context_.ready = true; });
}

void ServerCore::start_draining() {
  context_.draining = true;
  rooms_.close_all_sessions();
}

bool ServerCore::drained() const { return rooms_.session_count() == 0; }

void ServerCore::stop() {
  if (stopped_) return;
  stopped_ = true;
  rooms_.close_all_rooms();
  // Closed rooms stop their timers, so the pool runs out of work.
  workers_.join();
}

}  // namespace fw::server
