#include "avatar_store.hpp"

#include <openssl/evp.h>

#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "preview_package.hpp"

namespace fw::server {
namespace {

std::string content_id(std::span<const std::uint8_t> bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr);
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (unsigned int i = 0; i < 16 && i < length; ++i) {
    id += kHex[digest[i] >> 4];
    id += kHex[digest[i] & 15];
  }
  return id;
}

}  // namespace

bool is_asset_id(std::string_view text) {
  if (text.size() != 32) return false;
  for (const char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

AvatarStore::AvatarStore(std::filesystem::path directory, std::string& error)
    : directory_(std::move(directory) / "avatars") {
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  if (ec) error = "cannot create the avatar store " + directory_.string() + ": " + ec.message();
}

std::optional<StoredAvatar> AvatarStore::put(std::span<const std::uint8_t> package, std::string& error) {
  model::AvatarPackage parsed;
  if (!model::parse_avatar_package(package, parsed, error)) return std::nullopt;
  const std::string asset = content_id(package);
  if (auto known = get(asset)) return known;
  std::vector<std::uint8_t> preview;
  if (!make_preview_package(parsed, preview, error)) return std::nullopt;
  if (!model::write_file_atomically(directory_ / (asset + ".fwa"), package, error) ||
      !model::write_file_atomically(directory_ / (asset + ".preview.fwa"), preview, error))
    return std::nullopt;
  StoredAvatar stored{asset, std::make_shared<const std::vector<std::uint8_t>>(package.begin(), package.end()),
                      std::make_shared<const std::vector<std::uint8_t>>(std::move(preview))};
  std::lock_guard lock(mutex_);
  cache_.emplace(asset, stored);
  return stored;
}

std::optional<StoredAvatar> AvatarStore::get(const std::string& asset) {
  if (!is_asset_id(asset)) return std::nullopt;
  {
    std::lock_guard lock(mutex_);
    if (auto it = cache_.find(asset); it != cache_.end()) return it->second;
  }
  std::vector<std::uint8_t> full, preview;
  std::string error;
  if (!model::read_file(directory_ / (asset + ".fwa"), model::kMaxPackageBytes, full, error) ||
      !model::read_file(directory_ / (asset + ".preview.fwa"), model::kMaxPackageBytes, preview, error))
    return std::nullopt;
  StoredAvatar stored{asset, std::make_shared<const std::vector<std::uint8_t>>(std::move(full)),
                      std::make_shared<const std::vector<std::uint8_t>>(std::move(preview))};
  std::lock_guard lock(mutex_);
  return cache_.emplace(asset, stored).first->second;
}

}  // namespace fw::server
