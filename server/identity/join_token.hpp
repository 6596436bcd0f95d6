#pragma once
// Join tokens (server/PROTOCOL.md, "Join tokens"): an HMAC-SHA256-signed
// invitation of one named person to one room, until an expiry time.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fw::server {

struct TokenClaims {
  std::string room;
  std::string name;              ///< the invited person's display name (NFC)
  std::int64_t expires_unix = 0; ///< seconds since 1970
};

/// "fw1.PAYLOAD.SIGNATURE" for `claims`, signed with `secret`.
std::string mint_join_token(const TokenClaims& claims, std::string_view secret);

/// The claims of `token` if it is well formed, signed with `secret`, not
/// expired at `now_unix` and names a person; else nullopt and `why`, for the
/// person holding it.
std::optional<TokenClaims> verify_join_token(std::string_view token, std::string_view secret, std::int64_t now_unix,
                                             std::string& why);

/// Checks `token` for joining `room` as `name` at `now_unix`. Empty when it
/// admits; else why not, for the person (bad signature, expired, another
/// room, another name, no name).
std::string check_join_token(std::string_view token, std::string_view secret, std::string_view room,
                             std::string_view name, std::int64_t now_unix);

}  // namespace fw::server
