#pragma once
// What a room connection (ClientSession, whatever carries it) uses of the
// server, given whole when the session is made: ServerCore makes it once,
// and each session keeps a copy of these references. Nothing here is
// filled in later, and a session reaches nothing else of the server.
#include <atomic>
#include <string>
#include <vector>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include <boost/asio/thread_pool.hpp>

#include "avatar_store.hpp"
#include "look_store.hpp"
#include "metrics.hpp"
#include "server_config.hpp"
#include "token_holders.hpp"

namespace fw::server {

class RoomRegistry;
class SessionRegistry;

struct SessionServices {
  const ServerConfig& config;  ///< time-outs, the auth secret, budgets
  Metrics& metrics;
  AbuseLog& abuse;             ///< refusals by kind, for the log and /metrics
  TokenHolders& tokens;        ///< which connection holds each join token
  AddressLimits& addresses;    ///< joins and chat per address (config.abuse)
  AvatarStore& store;          ///< the uploaded avatars a hello names
  LookStore& looks;            ///< the saved looks a play-look command names
  /// Where a saved look is read (it may wait for the disk or Redis): never
  /// the connection's strand nor a room's.
  boost::asio::thread_pool& workers;
  RoomRegistry& rooms;         ///< the room a hello opens or joins
  SessionRegistry& sessions;   ///< the sessions open now, for a drain
  /// Faces for people who join without a package, chosen by name.
  const std::vector<StoredAvatar>& procedural_faces;
  /// Signs avatar keys (DATA/server.key; in a cluster, the cluster's).
  const std::string& server_key;
  const std::atomic<bool>& draining;  ///< SIGTERM: hellos are refused
};

}  // namespace fw::server
