#include "server_keys.hpp"

#include <array>
#include <fstream>
#include <iterator>
#include <system_error>

#include <fcntl.h>
#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <openssl/rand.h>
#include <unistd.h>

#include "base64url.hpp"

namespace fw::server {

std::string hmac_sha256(std::string_view secret, std::string_view data) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> mac{};
  unsigned int length = 0;
  HMAC(EVP_sha256(), secret.data(), static_cast<int>(secret.size()), reinterpret_cast<const unsigned char*>(data.data()),
       data.size(), mac.data(), &length);
  return std::string(reinterpret_cast<const char*>(mac.data()), length);
}

namespace {

std::string random_bytes(std::size_t n) {
  std::string bytes(n, '\0');
  if (RAND_bytes(reinterpret_cast<unsigned char*>(bytes.data()), static_cast<int>(n)) != 1) return {};
  return bytes;
}

constexpr std::size_t kServerKeyBytes = 32;

}  // namespace

std::string load_or_create_server_key(const std::filesystem::path& dir, std::string& error) {
  const auto path = dir / "server.key";
  std::ifstream in(path, std::ios::binary);
  if (in) {
    std::string key((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (key.size() == kServerKeyBytes) return key;
    error = path.string() + " is damaged (" + std::to_string(key.size()) +
            " bytes, not 32); remove it to make a new one (the avatar keys handed out so far stop working)";
    return {};
  }
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  const std::string key = random_bytes(kServerKeyBytes);
  if (key.empty()) {
    error = "no random bytes for the server key";
    return {};
  }
  // Written whole under another name, then renamed: a crash leaves either
  // no key or the whole key, never half of one.
  const auto temporary = dir / "server.key.new";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  bool ok = fd >= 0 && ::write(fd, key.data(), key.size()) == static_cast<ssize_t>(key.size()) && ::fsync(fd) == 0;
  if (fd >= 0) ok = ::close(fd) == 0 && ok;
  if (ok) std::filesystem::rename(temporary, path, ec);
  if (!ok || ec) {
    error = "cannot write " + path.string() + " (is the data directory writable?)";
    return {};
  }
  return key;
}

std::string new_asset_id() {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (const char byte : random_bytes(16)) {
    const auto b = static_cast<unsigned char>(byte);
    id += kHex[b >> 4];
    id += kHex[b & 15];
  }
  return id;  // empty only if the system has no random bytes
}

std::string avatar_key(std::string_view server_key, std::string_view asset) {
  const std::string mac = hmac_sha256(server_key, std::string("avatar-key:") + std::string(asset));
  return base64url(std::string_view(mac).substr(0, 16));
}

bool avatar_key_matches(std::string_view server_key, std::string_view asset, std::string_view key) {
  const std::string expected = avatar_key(server_key, asset);
  return key.size() == expected.size() && CRYPTO_memcmp(key.data(), expected.data(), expected.size()) == 0;
}

std::string random_key(std::size_t bytes) { return base64url(random_bytes(bytes)); }

std::string secret_hash(std::string_view secret) {
  if (secret.empty()) return {};
  const std::string digest = hmac_sha256("facewire secret", secret);
  return base64url(digest);
}

}  // namespace fw::server
