#pragma once
// Avatar packages by asset id (the package's content hash), in a local
// directory: DIR/avatars/ID.fwa and ID.preview.fwa. Every package is
// validated before it is stored; the preview is made on the way in. Held in
// memory once read; thread-safe.
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fw::server {

using SharedBytes = std::shared_ptr<const std::vector<std::uint8_t>>;  // as in room_connection.hpp

struct StoredAvatar {
  std::string asset;   ///< 32 lowercase hex digits
  SharedBytes full;
  SharedBytes preview;
};

class AvatarStore {
 public:
  /// Creates the directory if needed; `error` if it cannot.
  AvatarStore(std::filesystem::path directory, std::string& error);

  /// Validates `package` (.fwa bytes), makes its preview, stores both.
  /// nullopt and `error` (what is wrong with the package) if it is invalid.
  std::optional<StoredAvatar> put(std::span<const std::uint8_t> package, std::string& error);
  /// The avatar with `asset` id, or nullopt (unknown, or not an id).
  std::optional<StoredAvatar> get(const std::string& asset);

 private:
  std::filesystem::path directory_;
  std::mutex mutex_;
  std::map<std::string, StoredAvatar> cache_;
};

/// Whether `text` has the form of an asset id (so it is safe in a path).
bool is_asset_id(std::string_view text);

}  // namespace fw::server
