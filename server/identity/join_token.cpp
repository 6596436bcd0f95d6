#include "join_token.hpp"


#include <nlohmann/json.hpp>
#include <openssl/crypto.h>

#include "base64url.hpp"
#include "display_name.hpp"
#include "server_keys.hpp"

namespace fw::server {
namespace {

constexpr std::string_view kPrefix = "fw1.";
}  // namespace

std::string mint_join_token(const TokenClaims& claims, std::string_view secret) {
  nlohmann::json payload = {{"room", claims.room}, {"exp", claims.expires_unix}};
  if (!claims.name.empty()) payload["name"] = claims.name;
  std::string signed_part(kPrefix);
  signed_part += base64url(payload.dump());
  return signed_part + "." + base64url(hmac_sha256(secret, signed_part));
}

std::optional<TokenClaims> verify_join_token(std::string_view token, std::string_view secret, std::int64_t now_unix,
                                             std::string& why) {
  const auto refuse = [&why](std::string reason) -> std::optional<TokenClaims> {
    why = std::move(reason);
    return std::nullopt;
  };
  if (token.empty()) return refuse("this server needs a join token; ask the room's host for one");
  const auto dot = token.rfind('.');
  if (token.substr(0, kPrefix.size()) != kPrefix || dot == std::string_view::npos || dot < kPrefix.size())
    return refuse("the join token is malformed; ask for a new one");
  const std::string_view signed_part = token.substr(0, dot);
  std::string signature;
  // One spelling per signature: from_base64url refuses the others.
  if (!from_base64url(token.substr(dot + 1), signature)) return refuse("the join token is malformed; ask for a new one");
  const std::string expected = hmac_sha256(secret, signed_part);
  if (signature.size() != expected.size() || CRYPTO_memcmp(signature.data(), expected.data(), expected.size()) != 0)
    return refuse("the join token's signature is not valid here; ask for a new one");
  std::string payload_text;
  if (!from_base64url(signed_part.substr(kPrefix.size()), payload_text))
    return refuse("the join token is malformed; ask for a new one");
  const auto payload = nlohmann::json::parse(payload_text, nullptr, false);
  if (payload.is_discarded() || !payload.is_object() || !payload.contains("room") || !payload["room"].is_string() ||
      !payload.contains("exp") || !payload["exp"].is_number_integer())
    return refuse("the join token's content is malformed; ask for a new one");
  if (payload["exp"].get<std::int64_t>() < now_unix) return refuse("the join token has expired; ask for a new one");
  // A token admits one person: one without a name would admit anyone who
  // saw it, under any name.
  if (!payload.contains("name") || !payload["name"].is_string() || payload["name"].get<std::string>().empty())
    return refuse("the join token names nobody; ask the host for a token made with --name");
  // Names are compared as the hello's is, in NFC: a token minted elsewhere
  // with "Zoe\u0301" invites the Zoé who types it either way.
  std::string name;
  if (const std::string bad = normalize_display_name(payload["name"].get<std::string>(), name); !bad.empty())
    return refuse("the join token's name cannot be a display name (" + bad + "); ask the host for a new one");
  return TokenClaims{payload["room"].get<std::string>(), std::move(name), payload["exp"].get<std::int64_t>()};
}

std::string check_join_token(std::string_view token, std::string_view secret, std::string_view room,
                             std::string_view name, std::int64_t now_unix) {
  std::string why;
  const auto claims = verify_join_token(token, secret, now_unix, why);
  if (!claims) return why;
  if (claims->room != room) return "the join token is for another room";
  if (claims->name != name) return "the join token is for another name (" + claims->name.substr(0, 32) + ")";
  return {};
}

}  // namespace fw::server
