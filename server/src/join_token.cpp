#include "join_token.hpp"

#include <array>

#include <nlohmann/json.hpp>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

namespace fw::server {
namespace {

constexpr std::string_view kPrefix = "fw1.";
constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

std::string base64url(std::string_view bytes) {
  std::string out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (const char c : bytes) {
    buffer = (buffer << 8) | static_cast<std::uint8_t>(c);
    bits += 8;
    while (bits >= 6) {
      bits -= 6;
      out += kAlphabet[(buffer >> bits) & 63u];
    }
  }
  if (bits > 0) out += kAlphabet[(buffer << (6 - bits)) & 63u];
  return out;
}

bool from_base64url(std::string_view text, std::string& out) {
  out.clear();
  std::uint32_t buffer = 0;
  int bits = 0;
  for (const char c : text) {
    const auto at = kAlphabet.find(c);
    if (at == std::string_view::npos) return false;
    buffer = (buffer << 6) | static_cast<std::uint32_t>(at);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xFFu);
    }
  }
  return true;
}

std::string hmac_sha256(std::string_view secret, std::string_view data) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> mac{};
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret.data(), static_cast<int>(secret.size()), reinterpret_cast<const unsigned char*>(data.data()),
       data.size(), mac.data(), &length);
  return std::string(reinterpret_cast<const char*>(mac.data()), length);
}

}  // namespace

std::string mint_join_token(const TokenClaims& claims, std::string_view secret) {
  nlohmann::json payload = {{"room", claims.room}, {"exp", claims.expires_unix}};
  if (!claims.name.empty()) payload["name"] = claims.name;
  std::string signed_part(kPrefix);
  signed_part += base64url(payload.dump());
  return signed_part + "." + base64url(hmac_sha256(secret, signed_part));
}

std::string check_join_token(std::string_view token, std::string_view secret, std::string_view room,
                             std::string_view name, std::int64_t now_unix) {
  if (token.empty()) return "this server needs a join token; ask the room's host for one";
  const auto dot = token.rfind('.');
  if (token.substr(0, kPrefix.size()) != kPrefix || dot == std::string_view::npos || dot < kPrefix.size())
    return "the join token is malformed; ask for a new one";
  const std::string_view signed_part = token.substr(0, dot);
  std::string signature;
  if (!from_base64url(token.substr(dot + 1), signature)) return "the join token is malformed; ask for a new one";
  const std::string expected = hmac_sha256(secret, signed_part);
  if (signature.size() != expected.size() || CRYPTO_memcmp(signature.data(), expected.data(), expected.size()) != 0)
    return "the join token's signature is not valid here; ask for a new one";
  std::string payload_text;
  if (!from_base64url(signed_part.substr(kPrefix.size()), payload_text))
    return "the join token is malformed; ask for a new one";
  const auto payload = nlohmann::json::parse(payload_text, nullptr, false);
  if (payload.is_discarded() || !payload.is_object() || !payload.contains("room") || !payload["room"].is_string() ||
      !payload.contains("exp") || !payload["exp"].is_number_integer())
    return "the join token's content is malformed; ask for a new one";
  if (payload["exp"].get<std::int64_t>() < now_unix) return "the join token has expired; ask for a new one";
  if (payload["room"].get<std::string>() != room) return "the join token is for another room";
  if (payload.contains("name") && (!payload["name"].is_string() || payload["name"].get<std::string>() != name))
    return "the join token is for another name";
  return {};
}

}  // namespace fw::server
