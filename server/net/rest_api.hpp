#pragma once
// The HTTP API beside the static files (PROTOCOL.md, "HTTP API"): packages,
// rooms, readiness and metrics. Uploads are asynchronous and live in
// photo_preparation.hpp.
#include <optional>
#include <string>
#include <vector>

#include <boost/asio/thread_pool.hpp>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "avatar_store.hpp"
#include "http_responses.hpp"
#include "look_store.hpp"
#include "metrics.hpp"
#include "physics_governor.hpp"
#include "server_config.hpp"
#include "server_state.hpp"

namespace fw::server {

class RoomRegistry;

/// What the API reads and changes of the server, made once with the
/// listeners (network_server.cpp).
struct ApiServices {
  const ServerConfig& config;  ///< who may use the API (api_access.hpp)
  Metrics& metrics;            ///< /metrics
  const PhysicsGovernor& physics_lod;  ///< /metrics: the share of faces on physics
  AbuseLog& abuse;             ///< refusals by kind, for the log and /metrics
  AvatarStore& store;          ///< packages to serve, avatars to delete
  RoomRegistry& rooms;         ///< /api/rooms, and the wearers of a deleted avatar
  const std::vector<StoredAvatar>& own_faces;  ///< the server's faces, nobody's to delete
  const std::string& server_key;  ///< checks an avatar's key before its deletion
  const ServerState& state;    ///< /readyz
  LookStore& looks;            ///< saved looks (look_api.hpp)
  AddressLimits& addresses;    ///< saved-look changes per address and per avatar
  /// Where saved-look requests are answered: the store may wait for the
  /// disk or Redis, which the I/O loop must not.
  boost::asio::thread_pool& workers;
};

/// The answer to a GET, HEAD or DELETE the API serves, or nullopt when the
/// target is not one of its routes.
std::optional<Response> respond_to_api(const ApiServices& services, const Request& request);

/// A JSON response.
Response json_response(boost::beast::http::status status, unsigned version, bool keep_alive, std::string body);

}  // namespace fw::server
