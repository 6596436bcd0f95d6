#include "server_core.hpp"

#include "demo_room.hpp"
#include "server_keys.hpp"

namespace fw::server {

ServerCore::ServerCore(const ServerConfig& config)
    : workers_(static_cast<std::size_t>(config.workers)) {
  context_.config = config;
  addresses_ = std::make_unique<AddressLimits>(config.abuse);
  context_.addresses = addresses_.get();
  context_.physics_lod.set_enabled(config.physics && config.physics_lod);
  context_.workers = &workers_;
  context_.sessions = &sessions_;
  context_.room_bus = &bus_;
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
  if (!make_demo_avatars(context_, error)) return false;
  const RoomServices services{context_.config, context_.metrics, context_.physics_lod, context_.abuse, workers_,
                              *store_, context_.demo_avatars, bus_, context_.draining};
  rooms_ = std::make_unique<RoomRegistry>(services, *addresses_);
  context_.rooms = rooms_.get();
  return true;
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
  sessions_.close_all();
}

bool ServerCore::drained() const { return sessions_.count() == 0; }

void ServerCore::stop() {
  if (stopped_) return;
  stopped_ = true;
  if (rooms_) rooms_->close_all_rooms();
  // Closed rooms stop their timers, so the pool runs out of work.
  workers_.join();
}

}  // namespace fw::server
