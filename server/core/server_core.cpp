#include "server_core.hpp"

#include "demo_room.hpp"
#include "server_keys.hpp"

namespace fw::server {
namespace {

std::vector<StoredAvatar> both(const std::vector<StoredAvatar>& a, const std::vector<StoredAvatar>& b) {
  std::vector<StoredAvatar> all = a;
  all.insert(all.end(), b.begin(), b.end());
  return all;
}

}  // namespace

std::unique_ptr<ServerCore> ServerCore::open(const ServerConfig& config, std::string& error) {
  auto metrics = std::make_unique<Metrics>();
  auto store = std::make_unique<AvatarStore>(config.data, *metrics, error);
  if (!error.empty()) {
    error += " (choose another directory with --data DIR)";
    return nullptr;
  }
  std::string server_key = load_or_create_server_key(config.data, error);
  if (server_key.empty()) return nullptr;
  auto demo_avatars = make_demo_avatars(config, *store, error);
  if (!demo_avatars) return nullptr;
  // Stored with or without the lobby: a cluster node seats them when it
  // comes to own the lobby, whatever it was started with.
  auto residents = store_resident_faces(*store, error);
  if (!residents) return nullptr;
  return std::unique_ptr<ServerCore>(new ServerCore(config, std::move(metrics), std::move(store), std::move(server_key),
                                                    std::move(*demo_avatars), std::move(*residents)));
}

ServerCore::ServerCore(const ServerConfig& config, std::unique_ptr<Metrics> metrics, std::unique_ptr<AvatarStore> store,
                       std::string server_key, std::vector<StoredAvatar> demo_avatars,
                       std::vector<StoredAvatar> residents)
    : config_(config),
      metrics_(std::move(metrics)),
      physics_lod_(config_.physics && config_.physics_lod),
      addresses_(config_.abuse),
      store_(std::move(store)),
      looks_(store_->directory()),
      server_key_(std::move(server_key)),
      demo_avatars_(std::move(demo_avatars)),
      residents_(std::move(residents)),
      own_faces_(both(demo_avatars_, residents_)),
      workers_(static_cast<std::size_t>(config_.workers)),
      face_stepper_([this](double seconds) { physics_lod_.observe_physics_work(seconds); }),
      speech_(static_cast<std::size_t>(config_.speech_threads), config_.speech_queue),
      rooms_(RoomServices{config_, *metrics_, physics_lod_, abuse_, workers_, *store_, demo_avatars_, bus_,
                          state_.draining, speech_, face_stepper_, &face_models_},
             addresses_),
      session_services_{config_, *metrics_, abuse_,         tokens_,     addresses_,      *store_,
                        looks_,  workers_,  rooms_,        sessions_,   demo_avatars_, server_key_,
                        state_.draining} {}

ServerCore::~ServerCore() { stop(); }

void ServerCore::open_demo_room() {
  if (!config_.demo_room) {
    state_.ready = true;
    return;
  }
  fw::server::open_demo_room(rooms_, residents_, [this] { state_.ready = true; });
}

void ServerCore::start_draining() {
  state_.draining = true;
  sessions_.close_all();
}

bool ServerCore::drained() const { return sessions_.count() == 0; }

void ServerCore::stop() {
  if (stopped_) return;
  stopped_ = true;
  rooms_.close_all_rooms();
  // Lines still waiting for a voice are not said: the rooms are closing.
  speech_.stop();
  // Closed rooms stop their timers, so the pool runs out of work.
  workers_.join();
}

}  // namespace fw::server
