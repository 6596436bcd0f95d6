#include "avatar_store.hpp"

#include <openssl/evp.h>
#include <spdlog/spdlog.h>

#include "fw/model/avatar_package.hpp"
#include "durable_file.hpp"
#include "fw/model/file_io.hpp"
#include "preview_package.hpp"
#include "shared_bytes.hpp"
#include "server_keys.hpp"

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

// Answers for a person (they end up in a closing reason of at most 120 bytes).
AvatarLookup being_prepared() {
  return {AvatarStatus::being_prepared, std::nullopt,
          "your avatar is being prepared again for this server's version; join again in a few seconds"};
}
AvatarLookup no_photo_to_remake_it() {
  return {AvatarStatus::out_of_date, std::nullopt,
          "your avatar was made by an older version and has no photo to remake it; upload your photo again"};
}
AvatarLookup cannot_remake_it() {
  return {AvatarStatus::out_of_date, std::nullopt,
          "your avatar was made by an older version and could not be remade; upload your photo again"};
}
AvatarLookup damaged() {
  return {AvatarStatus::damaged, std::nullopt, "your stored avatar is damaged; upload your photo again"};
}
AvatarLookup deleted() {
  return {AvatarStatus::deleted, std::nullopt,
          "this avatar was deleted by whoever uploaded it; upload your own photo to make one"};
}

// The saved looks (look_store.hpp) go with the avatar.
constexpr const char* kAvatarFiles[] = {".fwa", ".preview.fwa", ".photo", ".looks"};

// The preview beside a package, made again when it is missing or does not
// parse (a crash between writing the package and its preview). Writing it
// back only saves the work next time: the preview is served either way.
bool read_or_make_preview(const std::filesystem::path& path, const model::AvatarPackage& full,
                          std::vector<std::uint8_t>& preview, std::string& error) {
  model::AvatarPackage parsed;
  if (model::read_file(path, model::kMaxPackageBytes, preview, error) &&
      model::parse_avatar_package(preview, parsed, error))
    return true;
  if (!make_preview_package(full, preview, error)) return false;
  if (!write_file_durably(path, preview, error)) spdlog::warn("{}", error);
  return true;
}

}  // namespace

bool is_asset_id(std::string_view text) {
  if (text.size() != 32) return false;
  for (const char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

AvatarStore::AvatarStore(std::filesystem::path directory, Metrics& metrics, std::string& error)
    : directory_(std::move(directory) / "avatars"), metrics_(metrics) {
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  if (ec) {
    error = "cannot create the avatar store " + directory_.string() + ": " + ec.message();
    return;
  }
  // What a crash mid-write left: never a stored file (they are only ever
  // renamed into place whole), so nothing refers to them.
  if (const auto removed = remove_temporary_files(directory_))
    spdlog::info("removed {} temporary file(s) an interrupted write left in {}", removed, directory_.string());
}

std::filesystem::path AvatarStore::file(const std::string& asset, const char* suffix) const {
  return directory_ / (asset + suffix);
}

void AvatarStore::set_repreparer(AvatarRepreparer repreparer) {
  std::lock_guard lock(mutex_);
  repreparer_ = std::move(repreparer);
}

std::optional<StoredAvatar> AvatarStore::put(std::span<const std::uint8_t> package, std::span<const std::uint8_t> photo,
                                             std::string& error) {
  model::AvatarPackage parsed;
  if (!model::parse_avatar_package(package, parsed, error)) return std::nullopt;
  const std::string asset = new_asset_id();
  if (asset.empty()) {
    error = "the server found no random numbers for a new avatar id; try again";
    return std::nullopt;
  }
  // The photo goes first: a crash before the package leaves only a photo
  // that no id refers to yet.
  if (!photo.empty() && !write_file_durably(file(asset, ".photo"), photo, error, Durability::synced))
    return std::nullopt;
  auto stored = write_and_remember(asset, package, parsed, error, Durability::synced);
  if (stored && replica_.share) replica_.share(asset, package, photo);
  return stored;
}

std::optional<StoredAvatar> AvatarStore::put_own_face(std::span<const std::uint8_t> package, std::string& error,
                                                      Durability durability) {
  model::AvatarPackage parsed;
  if (!model::parse_avatar_package(package, parsed, error)) return std::nullopt;
  const std::string asset = content_id(package);
  const AvatarLookup known = lookup(asset);
  if (known.status == AvatarStatus::found) return known.avatar;
  if (known.status == AvatarStatus::being_prepared) {
    error = known.message;
    return std::nullopt;
  }
  // Bytes with this id's hash are the face it was first stored with, so
  // they may repair a damaged or out-of-date one.
  auto stored = write_and_remember(asset, package, parsed, error, durability);
  if (stored && replica_.share) replica_.share(asset, package, {});
  return stored;
}

bool AvatarStore::remove(const std::string& asset) {
  if (!is_asset_id(asset)) return false;
  const bool removed = remove_here(asset);
  // Also when only the cluster had it: the copy goes, and every node is told.
  if (replica_.remove) replica_.remove(asset);
  if (removed) {
    spdlog::info("avatar {} deleted by its uploader", asset);
    metrics_.deleted_avatars.fetch_add(1);
  }
  return removed;
}

void AvatarStore::forget(const std::string& asset) {
  if (is_asset_id(asset) && remove_here(asset)) spdlog::info("avatar {} deleted on another node: dropped here", asset);
}

bool AvatarStore::remove_here(const std::string& asset) {
  {
    std::lock_guard lock(mutex_);
    // Remembered first: a lookup or a preparation that ends from now on
    // finds it deleted rather than bringing it back.
    deleted_.insert(asset);
    cache_.erase(asset);
    refused_.erase(asset);
    preparing_.erase(asset);
  }
  bool removed = false;
  for (const char* suffix : kAvatarFiles) {
    std::error_code ec;
    removed = std::filesystem::remove(file(asset, suffix), ec) || removed;
  }
  return removed;
}

std::vector<std::string> AvatarStore::stored_assets() const {
  std::vector<std::string> assets;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() == 36 && name.ends_with(".fwa") && is_asset_id(name.substr(0, 32))) assets.push_back(name.substr(0, 32));
  }
  return assets;
}

bool AvatarStore::read_files(const std::string& asset, std::vector<std::uint8_t>& package,
                             std::vector<std::uint8_t>& photo) const {
  std::string error;
  if (!is_asset_id(asset) || !model::read_file(file(asset, ".fwa"), model::kMaxPackageBytes, package, error))
    return false;
  std::error_code ec;
  if (std::filesystem::exists(file(asset, ".photo"), ec))
    model::read_file(file(asset, ".photo"), kMaxStoredPhotoBytes, photo, error);
  return true;
}

std::optional<StoredAvatar> AvatarStore::write_and_remember(const std::string& asset,
                                                            std::span<const std::uint8_t> package,
                                                            const model::AvatarPackage& parsed, std::string& error,
                                                            Durability durability) {
  std::vector<std::uint8_t> preview;
  if (!make_preview_package(parsed, preview, error) ||
      !write_file_durably(file(asset, ".fwa"), package, error, durability) ||
      !write_file_durably(file(asset, ".preview.fwa"), preview, error, durability))
    return std::nullopt;
  StoredAvatar stored{asset, content_id(package), share(std::vector<std::uint8_t>(package.begin(), package.end())),
                      share(std::move(preview))};
  std::unique_lock lock(mutex_);
  if (deleted_.contains(asset)) {
    // Deleted while this preparation ran: what it just wrote goes too.
    lock.unlock();
    for (const char* suffix : kAvatarFiles) {
      std::error_code ec;
      std::filesystem::remove(file(asset, suffix), ec);
    }
    error = "the avatar was deleted meanwhile";
    return std::nullopt;
  }
  refused_.erase(asset);
  preparing_.erase(asset);
  return cache_.insert_or_assign(asset, stored).first->second;
}

AvatarLookup AvatarStore::lookup(const std::string& asset) {
  if (!is_asset_id(asset)) return {};
  AvatarLookup found;
  {
    std::lock_guard lock(mutex_);
    if (deleted_.contains(asset)) return deleted();
    if (auto it = cache_.find(asset); it != cache_.end()) found = {AvatarStatus::found, it->second, {}};
    else if (preparing_.contains(asset)) return being_prepared();
    else if (auto refused = refused_.find(asset); refused != refused_.end()) return refused->second;
  }
  if (found.status != AvatarStatus::found) found = load(asset);
  if (found.status == AvatarStatus::found) note_use(asset);
  return found;
}

void AvatarStore::note_use(const std::string& asset) {
  const auto now = std::chrono::steady_clock::now();
  {
    std::lock_guard lock(mutex_);
    auto [it, first] = last_noted_.try_emplace(asset, now);
    if (!first && now - it->second < std::chrono::hours(1)) return;
    it->second = now;
  }
  std::error_code ec;
  std::filesystem::last_write_time(file(asset, ".fwa"), std::filesystem::file_time_type::clock::now(), ec);
  if (replica_.touch) replica_.touch(asset);
}

std::vector<std::string> AvatarStore::remove_unused_since(std::filesystem::file_time_type cutoff,
                                                          const std::set<std::string>& keep) {
  std::vector<std::string> removed;
  for (const std::string& asset : stored_assets()) {
    if (keep.contains(asset)) continue;
    std::error_code ec;
    const auto last_use = std::filesystem::last_write_time(file(asset, ".fwa"), ec);
    if (ec || last_use >= cutoff) continue;
    remove_here(asset);
    {
      // Not deleted by its uploader: an upload of the same id cannot come,
      // but the cluster's copy may still bring it back here while it lives.
      std::lock_guard lock(mutex_);
      deleted_.erase(asset);
      last_noted_.erase(asset);
    }
    removed.push_back(asset);
    metrics_.expired_avatars.fetch_add(1);
  }
  return removed;
}

AvatarLookup AvatarStore::load(const std::string& asset) {
  std::error_code ec;
  if (!std::filesystem::exists(file(asset, ".fwa"), ec) && !fetch_from_replica(asset)) return {};
  std::vector<std::uint8_t> full, preview;
  std::string error;
  model::AvatarPackage parsed;
  auto why = model::PackageRefusal::damaged;
  if (!model::read_file(file(asset, ".fwa"), model::kMaxPackageBytes, full, error) ||
      !model::parse_avatar_package(full, parsed, error, why)) {
    if (why != model::PackageRefusal::damaged) return out_of_date(asset, error);
    spdlog::error("stored avatar {} is corrupt and refused: {}", asset, error);
    metrics_.damaged_avatars.fetch_add(1);
    refuse(asset, damaged());
    return damaged();
  }
  if (!read_or_make_preview(file(asset, ".preview.fwa"), parsed, preview, error))
    spdlog::warn("avatar {}: its preview cannot be made again ({}); it is served without one", asset, error);
  StoredAvatar stored{asset, content_id(full), share(std::move(full)), share(std::move(preview))};
  std::lock_guard lock(mutex_);
  return {AvatarStatus::found, cache_.emplace(asset, stored).first->second, {}};
}

bool AvatarStore::fetch_from_replica(const std::string& asset) {
  // Uploaded on another node of the cluster: kept here from now on.
  std::vector<std::uint8_t> package, photo;
  if (!replica_.fetch || !replica_.fetch(asset, package, photo)) return false;
  std::string error;
  if ((!photo.empty() && !write_file_durably(file(asset, ".photo"), photo, error, Durability::synced)) ||
      !write_file_durably(file(asset, ".fwa"), package, error, Durability::synced)) {
    spdlog::warn("avatar {} from the cluster could not be kept here: {}", asset, error);
    return false;
  }
  return true;
}

AvatarLookup AvatarStore::out_of_date(const std::string& asset, const std::string& why) {
  std::vector<std::uint8_t> photo;
  std::string no_photo;
  const bool has_photo = model::read_file(file(asset, ".photo"), kMaxStoredPhotoBytes, photo, no_photo);
  AvatarRepreparer repreparer;
  {
    std::lock_guard lock(mutex_);
    if (preparing_.contains(asset)) return being_prepared();  // another thread was first
    if (has_photo && repreparer_) {
      preparing_.insert(asset);
      repreparer = repreparer_;
    }
  }
  if (repreparer) {
    spdlog::info("avatar {} is out of date ({}); preparing it again from its photo", asset, why);
    metrics_.repreparations_started.fetch_add(1);
    repreparer(asset, std::move(photo));
    return being_prepared();
  }
  spdlog::warn("avatar {} is out of date ({}) and refused: {}", asset, why,
               has_photo ? "this server cannot prepare photos" : "no photo is stored with it");
  metrics_.outdated_avatars.fetch_add(1);
  const AvatarLookup refusal = has_photo ? cannot_remake_it() : no_photo_to_remake_it();
  refuse(asset, refusal);
  return refusal;
}

bool AvatarStore::replace(const std::string& asset, std::span<const std::uint8_t> package, std::string& error) {
  {
    std::lock_guard lock(mutex_);
    if (deleted_.contains(asset)) {
      error = "the avatar was deleted meanwhile";
      return false;  // nothing to count: it is gone, as its uploader asked
    }
  }
  model::AvatarPackage parsed;
  if (model::parse_avatar_package(package, parsed, error) && write_and_remember(asset, package, parsed, error)) {
    spdlog::info("avatar {} prepared again from its photo ({} bytes)", asset, package.size());
    std::vector<std::uint8_t> stored_package, photo;
    if (replica_.share && read_files(asset, stored_package, photo)) replica_.share(asset, package, photo);
    metrics_.repreparations.fetch_add(1);
    return true;
  }
  preparation_failed(asset, error);
  return false;
}

void AvatarStore::preparation_failed(const std::string& asset, const std::string& why) {
  spdlog::warn("avatar {} could not be prepared again from its photo and is refused until a restart: {}", asset, why);
  metrics_.repreparation_failures.fetch_add(1);
  std::lock_guard lock(mutex_);
  preparing_.erase(asset);
  refused_.insert_or_assign(asset, cannot_remake_it());
}

void AvatarStore::refuse(const std::string& asset, const AvatarLookup& refusal) {
  std::lock_guard lock(mutex_);
  refused_.insert_or_assign(asset, refusal);
}

}  // namespace fw::server
