#pragma once
// What a cluster node (cluster_node.hpp) uses of the server it is part of,
// given whole when the node is made (network_server.cpp makes it once from
// the ServerCore). Nothing here is filled in later.
#include <atomic>
#include <string>
#include <vector>

#include <boost/asio/thread_pool.hpp>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "avatar_store.hpp"
#include "look_store.hpp"
#include "room_bus_relay.hpp"
#include "room_registry.hpp"
#include "server_config.hpp"
#include "server_state.hpp"
#include "session_registry.hpp"
#include "token_holders.hpp"

namespace fw::server {

struct ClusterServices {
  const ServerConfig& config;  ///< the lobby, avatar retention, the limits others' news is held to
  AbuseLog& abuse;             ///< messages on Redis no node could have sent
  AddressLimits& addresses;    ///< spending and connections shared with the other nodes
  TokenHolders& tokens;        ///< join tokens held here and elsewhere
  AvatarStore& store;          ///< its copies in Redis
  LookStore& looks;            ///< the avatars' saved looks, kept in Redis beside them
  /// Signs avatar keys: the node puts the cluster's in its place before
  /// any request is served.
  std::string& server_key;
  /// The faces the lobby's residents wear, when this node comes to own it.
  const std::vector<StoredAvatar>& lobby_faces;
  boost::asio::thread_pool& workers;  ///< where avatars are dropped and shared again
  RoomBusRelay& room_bus;      ///< the node attaches itself while it runs
  RoomRegistry& rooms;         ///< the rooms this node holds
  const SessionRegistry& sessions;  ///< this node's load
  ServerState& state;          ///< cluster_up for /readyz; draining
};

}  // namespace fw::server
