#pragma once
// Who may use the HTTP API when the server is not open to everyone
// (PROTOCOL.md 9.3): with --auth-secret, uploads and the room list need a
// join token (the invite link's, in the browser), and the room list shows
// only the room that token opens; /metrics needs the operator's secret
// (--metrics-secret) whenever one is set, and is closed with --auth-secret
// and none.
#include <optional>
#include <string>

#include "http_responses.hpp"
#include "join_token.hpp"
#include "server_config.hpp"

namespace fw::server {

/// The token `request` carries: "Authorization: Bearer T", else "token=T"
/// in its query; empty if none.
std::string request_token(const Request& request);

/// What a request may see, once its token is checked.
struct ApiAccess {
  bool open = true;                  ///< no --auth-secret: everything
  std::optional<TokenClaims> claims; ///< the token's, when the server needs one
};

/// The access `request` has to uploads and the room list, or the 401
/// answer (in `refusal`) that says what is missing.
/// `config`: its auth secret.
std::optional<ApiAccess> api_access(const ServerConfig& config, const Request& request, Response& refusal);

/// Whether `request` may read /metrics; else `refusal` says why.
/// `config`: its metrics and auth secrets.
bool operator_access(const ServerConfig& config, const Request& request, Response& refusal);

}  // namespace fw::server
