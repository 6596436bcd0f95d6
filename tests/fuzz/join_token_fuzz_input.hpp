#pragma once
// The layout of join_token_fuzz's input, shared with fuzz_make_seeds:
//   byte 0      how the token is made (TokenMaking), plus kChangeSignature
//   bytes 1..8  now, seconds since 1970 (int64, little-endian)
//   byte 9      minted tokens expire this many seconds after now (int8)
//   bytes 10,11 which character of an admitted token's signature to change,
//               and to which base64url character
//   then        secret, room, name and text, separated by NUL bytes: the
//               token itself (raw), or the payload to sign (signed)
// and signed_token(), which makes a token of any payload.
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <openssl/evp.h>
#include <openssl/hmac.h>

namespace fw::fuzz {

inline constexpr std::string_view kBase64urlAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

inline std::string base64url(std::string_view bytes) {
  std::string out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (const char c : bytes) {
    buffer = (buffer << 8) | static_cast<std::uint8_t>(c);
    for (bits += 8; bits >= 6; bits -= 6) out += kBase64urlAlphabet[(buffer >> (bits - 6)) & 63u];
  }
  if (bits > 0) out += kBase64urlAlphabet[(buffer << (6 - bits)) & 63u];
  return out;
}

/// "fw1." + the payload + "." + its HMAC-SHA256 under `secret`, as
/// PROTOCOL.md ("Join tokens") spells a token, whatever the payload holds:
/// the fuzzer's way past a signature it could never guess.
inline std::string signed_token(std::string_view payload, std::string_view secret) {
  const std::string signed_part = "fw1." + base64url(payload);
  std::array<unsigned char, EVP_MAX_MD_SIZE> mac{};
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret.data(), static_cast<int>(secret.size()),
       reinterpret_cast<const unsigned char*>(signed_part.data()), signed_part.size(), mac.data(), &length);
  return signed_part + "." + base64url({reinterpret_cast<const char*>(mac.data()), length});
}

enum class TokenMaking : std::uint8_t {
  raw = 0,     ///< the text is the token
  signed_ = 1, ///< the text is a payload, signed with the secret here
  minted = 2,  ///< mint_join_token for the room and name
};

struct JoinTokenInput {
  static constexpr std::size_t kHeaderBytes = 12;
  static constexpr std::uint8_t kChangeSignature = 0x04;

  TokenMaking making = TokenMaking::raw;
  bool change_signature = false;
  std::int64_t now = 0;
  std::int64_t expires = 0;  ///< now + the input's offset, saturated
  std::uint8_t change_at = 0, change_to = 0;
  std::string_view secret, room, name, text;

  static std::optional<JoinTokenInput> parse(std::span<const std::uint8_t> bytes) {
    if (bytes.size() < kHeaderBytes) return std::nullopt;
    JoinTokenInput in;
    const int making = bytes[0] & 3;
    in.making = making == 3 ? TokenMaking::raw : static_cast<TokenMaking>(making);
    in.change_signature = (bytes[0] & kChangeSignature) != 0;
    std::uint64_t now = 0;
    for (int i = 0; i < 8; ++i) now |= std::uint64_t{bytes[1 + i]} << (8 * i);
    in.now = static_cast<std::int64_t>(now);
    const auto offset = static_cast<std::int8_t>(bytes[9]);
    using limits = std::numeric_limits<std::int64_t>;
    if (offset > 0 && in.now > limits::max() - offset) in.expires = limits::max();
    else if (offset < 0 && in.now < limits::min() - offset) in.expires = limits::min();
    else in.expires = in.now + offset;
    in.change_at = bytes[10];
    in.change_to = bytes[11];
    std::string_view rest(reinterpret_cast<const char*>(bytes.data() + kHeaderBytes), bytes.size() - kHeaderBytes);
    std::string_view* fields[] = {&in.secret, &in.room, &in.name};
    for (std::string_view* field : fields) {
      const auto nul = rest.find('\0');
      if (nul == std::string_view::npos) return std::nullopt;
      *field = rest.substr(0, nul);
      rest.remove_prefix(nul + 1);
    }
    in.text = rest;
    return in;
  }

  static std::vector<std::uint8_t> make(TokenMaking making, bool change_signature, std::int64_t now,
                                        std::int8_t expires_after, std::string_view secret, std::string_view room,
                                        std::string_view name, std::string_view text, std::uint8_t change_at = 0,
                                        std::uint8_t change_to = 0) {
    std::vector<std::uint8_t> bytes = {
        static_cast<std::uint8_t>(static_cast<std::uint8_t>(making) | (change_signature ? kChangeSignature : 0))};
    for (int i = 0; i < 8; ++i) bytes.push_back(static_cast<std::uint8_t>(static_cast<std::uint64_t>(now) >> (8 * i)));
    bytes.push_back(static_cast<std::uint8_t>(expires_after));
    bytes.push_back(change_at);
    bytes.push_back(change_to);
    for (const std::string_view field : {secret, room, name}) {
      bytes.insert(bytes.end(), field.begin(), field.end());
      bytes.push_back(0);
    }
    bytes.insert(bytes.end(), text.begin(), text.end());
    return bytes;
  }
};

}  // namespace fw::fuzz
