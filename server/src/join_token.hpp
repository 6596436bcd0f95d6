#pragma once
// Join tokens (server/PROTOCOL.md, "Join tokens"): an HMAC-SHA256-signed
// invitation to one room, optionally for one name, until an expiry time.
#include <cstdint>
#include <string>
#include <string_view>

namespace fw::server {

struct TokenClaims {
  std::string room;
  std::string name;              ///< empty: any name
  std::int64_t expires_unix = 0; ///< seconds since 1970
};

/// "fw1.PAYLOAD.SIGNATURE" for `claims`, signed with `secret`.
std::string mint_join_token(const TokenClaims& claims, std::string_view secret);

/// Checks `token` for joining `room` as `name` at `now_unix`. Empty when it
/// admits; else why not, for the person (bad signature, expired, another room).
std::string check_join_token(std::string_view token, std::string_view secret, std::string_view room,
                             std::string_view name, std::int64_t now_unix);

}  // namespace fw::server
