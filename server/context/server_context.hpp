#pragma once
// What every part of a running server shares: its configuration, metrics,
// avatar store, rooms, the worker pool rooms tick on, and whether it drains.
// ServerCore (server_core.hpp) owns and fills it.
#include <atomic>
#include <memory>
#include <vector>

#include <boost/asio/thread_pool.hpp>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "avatar_store.hpp"
#include "metrics.hpp"
#include "physics_governor.hpp"
#include "token_holders.hpp"
#include "server_config.hpp"

namespace fw::server {

class RoomRegistry;
class RoomBusRelay;
class SessionRegistry;

struct ServerContext {
  ServerConfig config;
  Metrics metrics;
  PhysicsGovernor physics_lod;  ///< physics level of detail under load (config.physics_lod)
  boost::asio::thread_pool* workers = nullptr; ///< room ticks, encoding
  AvatarStore* store = nullptr;
  AddressLimits* addresses = nullptr;  ///< per-address connections, rates and upload bytes (config.abuse)
  AbuseLog abuse;                      ///< refusals by kind, for the log and /metrics
  TokenHolders tokens;                 ///< which connection holds each join token
  std::string server_key;              ///< signs avatar keys (DATA/server.key)
  RoomRegistry* rooms = nullptr;       ///< made once the avatar store is open
  SessionRegistry* sessions = nullptr;  ///< the client sessions open now
  /// The bus every room holds (room_bus_relay.hpp): a cluster node attaches itself to it.
  RoomBusRelay* room_bus = nullptr;
  /// Procedural faces for clients that join without a package (and the lobby).
  std::vector<StoredAvatar> demo_avatars;
  std::atomic<bool> ready{false};     ///< /readyz: listening and the demo room seated
  std::atomic<bool> draining{false};
  std::atomic<bool> cluster_up{true};  ///< /readyz: a cluster node reaches Redis (always, in one process)  ///< SIGTERM: no new joins, sessions told to leave
};

}  // namespace fw::server
