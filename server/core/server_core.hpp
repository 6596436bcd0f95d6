#pragma once
// Everything a running server holds apart from its sockets: its
// configuration, metrics and limits, the avatar store with the demo faces,
// the worker pool that ticks the rooms, the rooms, and the sessions open.
// `facewire-server serve` puts listeners in front of it
// (network_server.hpp); tests and benchmarks put in-memory sessions in
// front of it (in_memory_session.hpp).
//
// Made whole in one place, in order (open()): the avatar store, the server
// key and the demo faces first, since everything after them holds them;
// then the rooms and what sessions use, by reference. A core that exists is
// usable at once; one that cannot be made is never half made. Each part
// above receives the few of these it uses (SessionServices, RoomServices,
// and the services of the parts above core), never the core itself.
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/thread_pool.hpp>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "avatar_store.hpp"
#include "look_store.hpp"
#include "metrics.hpp"
#include "physics_governor.hpp"
#include "room_bus_relay.hpp"
#include "room_registry.hpp"
#include "server_config.hpp"
#include "server_state.hpp"
#include "session_registry.hpp"
#include "session_services.hpp"
#include "token_holders.hpp"

namespace fw::server {

class ServerCore {
 public:
  /// Opens the avatar store (config.data), the server key and the demo
  /// faces, then makes everything that holds them; null and `error`, for
  /// the person starting the server, if any of the three fails.
  static std::unique_ptr<ServerCore> open(const ServerConfig& config, std::string& error);
  /// Stops the rooms and waits for the worker pool.
  ~ServerCore();
  ServerCore(const ServerCore&) = delete;
  ServerCore& operator=(const ServerCore&) = delete;

  /// Opens the demo room when the configuration asks for one, and marks the
  /// server ready (/readyz) once its faces are seated.
  void open_demo_room();

  /// No new joins; every open session is told that the server shuts down.
  void start_draining();
  /// Every session has left.
  bool drained() const;
  /// Closes every room and waits until the worker pool has nothing left to do.
  void stop();

  const ServerConfig& config() const { return config_; }
  Metrics& metrics() { return *metrics_; }
  AbuseLog& abuse() { return abuse_; }
  PhysicsGovernor& physics_lod() { return physics_lod_; }
  AddressLimits& addresses() { return addresses_; }
  TokenHolders& tokens() { return tokens_; }
  AvatarStore& store() { return *store_; }
  /// The avatars' saved looks, kept beside them (look_store.hpp).
  LookStore& looks() { return looks_; }
  /// Signs avatar keys: DATA/server.key, until a cluster node adopts the
  /// cluster's (before any request is served).
  std::string& server_key() { return server_key_; }
  /// Procedural faces for clients that join without a package.
  const std::vector<StoredAvatar>& demo_avatars() const { return demo_avatars_; }
  /// The lobby's residents' faces, prepared from portraits (resident_faces.hpp).
  const std::vector<StoredAvatar>& residents() const { return residents_; }
  /// Both: the server's own faces, nobody's to delete and never swept.
  const std::vector<StoredAvatar>& own_faces() const { return own_faces_; }
  ServerState& state() { return state_; }
  boost::asio::thread_pool& workers() { return workers_; }
  FaceModels& face_models() { return face_models_; }
  FaceStepper& face_stepper() { return face_stepper_; }
  SpeechWorker& speech() { return speech_; }
  /// The bus every room holds (room_bus_relay.hpp): a cluster node attaches itself to it.
  RoomBusRelay& room_bus() { return bus_; }
  RoomRegistry& rooms() { return rooms_; }
  SessionRegistry& sessions() { return sessions_; }
  /// What every room connection is made with.
  const SessionServices& session_services() const { return session_services_; }

 private:
  ServerCore(const ServerConfig& config, std::unique_ptr<Metrics> metrics, std::unique_ptr<AvatarStore> store,
             std::string server_key, std::vector<StoredAvatar> demo_avatars, std::vector<StoredAvatar> residents);

  const ServerConfig config_;
  /// Made before the store, which counts into it, and so apart.
  std::unique_ptr<Metrics> metrics_;
  AbuseLog abuse_;
  PhysicsGovernor physics_lod_;  ///< physics level of detail under load (config.physics_lod)
  TokenHolders tokens_;
  AddressLimits addresses_;  ///< per-address connections, rates and upload bytes (config.abuse)
  std::unique_ptr<AvatarStore> store_;
  LookStore looks_;
  std::string server_key_;
  const std::vector<StoredAvatar> demo_avatars_;
  const std::vector<StoredAvatar> residents_;
  const std::vector<StoredAvatar> own_faces_;
  ServerState state_;
  /// Every avatar's own face, by package version (face_models.hpp); before
  /// the workers, which build into it until they are joined.
  FaceModels face_models_;
  boost::asio::thread_pool workers_;  ///< room ticks, encoding
  FaceStepper face_stepper_;          ///< the rooms' physics faces, stepped together on workers_
  SpeechWorker speech_;               ///< chat lines' lip-sync tracks (speech_worker.hpp)
  RoomBusRelay bus_;
  SessionRegistry sessions_;
  RoomRegistry rooms_;
  const SessionServices session_services_;
  bool stopped_ = false;
};

}  // namespace fw::server
