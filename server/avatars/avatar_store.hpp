#pragma once
// Avatars by asset id, in a local directory: DIR/avatars/ID.fwa (the
// package), ID.preview.fwa (its preview, made on the way in) and ID.photo
// (the photo it was prepared from, as uploaded, when there was one). Every
// file is written atomically and durably (durable_file.hpp): a crash or a
// power cut leaves it whole or absent. Held in memory once read; thread-safe.
//
// The id names the stored avatar, and stays when its package is prepared
// again from the photo (after the package format or the generic face
// changed), because people and rooms refer to it. Every upload makes a new
// avatar under a new random id, even of bytes already stored: packages are
// public (every room member downloads them), so an id derived from the
// bytes would let anyone who saw a face upload it again and be handed its
// key (server_keys.hpp). The server's own faces (the demo faces, made again
// at every start) are the exception: their id is their package's hash, so a
// start finds the ones it made before. Avatars stored before ids were random
// have such ids too. An upload never changes a stored avatar, so an id keeps
// the face its uploader gave it until the uploader deletes it.
#include <chrono>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "durable_file.hpp"
#include "metrics.hpp"
#include "shared_bytes.hpp"

namespace fw::model {
struct AvatarPackage;
}

namespace fw::server {

struct StoredAvatar {
  std::string asset;    ///< the avatar's id: 32 lowercase hex digits
  std::string version;  ///< the content hash of its current package (an HTTP ETag)
  SharedBytes full;
  SharedBytes preview;
};

/// The largest photo kept beside a package: the preparer's own limit
/// (fw/photo/photo_limits.hpp), so no stored photo is one it would refuse.
inline constexpr std::size_t kMaxStoredPhotoBytes = 10'000'000;

/// What became of a request for an avatar.
enum class AvatarStatus {
  found,           ///< `avatar` holds it
  unknown,         ///< no avatar has this id (or it is not an id)
  being_prepared,  ///< out of date and being prepared again from its photo: ask again in a few seconds
  out_of_date,     ///< out of date and it cannot be prepared again here: upload the photo again
  damaged,         ///< the stored package is corrupt: upload the avatar again
  deleted,         ///< its uploader deleted it (since this server started)
};

struct AvatarLookup {
  AvatarStatus status = AvatarStatus::unknown;
  std::optional<StoredAvatar> avatar;  ///< when found
  std::string message;                 ///< otherwise: what is wrong and what to do, for a person
};

/// Prepares an out-of-date avatar again from its photo, off the caller's
/// thread, and ends with AvatarStore::replace or AvatarStore::preparation_failed.
using AvatarRepreparer = std::function<void(const std::string& asset, std::vector<std::uint8_t> photo)>;

/// The cluster's copy of every avatar (cluster mode): `share` is handed
/// each avatar this node stores (its package and photo) before the store
/// answers, `fetch` is asked for one this node does not have, and `remove`
/// is told of one its uploader deleted here (it drops the copy and tells
/// the other nodes, which drop theirs with AvatarStore::forget).
struct AvatarReplica {
  std::function<void(const std::string& asset, std::span<const std::uint8_t> package,
                     std::span<const std::uint8_t> photo)>
      share;
  std::function<bool(const std::string& asset, std::vector<std::uint8_t>& package, std::vector<std::uint8_t>& photo)>
      fetch;
  /// `asset` was used here (at most once an hour): its copy's expiry starts again.
  std::function<void(const std::string& asset)> touch;
  std::function<void(const std::string& asset)> remove;
};

class AvatarStore {
 public:
  /// Creates the directory if needed; `error` if it cannot.
  AvatarStore(std::filesystem::path directory, Metrics& metrics, std::string& error);

  /// An upload: validates `package` (.fwa bytes), makes its preview, and
  /// stores both and `photo` (the one the package was prepared from; may be
  /// empty; written first) as a new avatar under a new id, whatever is
  /// stored already. nullopt and `error` (what is wrong with the package)
  /// if it is invalid or cannot be written.
  std::optional<StoredAvatar> put(std::span<const std::uint8_t> package, std::span<const std::uint8_t> photo,
                                  std::string& error);
  std::optional<StoredAvatar> put(std::span<const std::uint8_t> package, std::string& error) {
    return put(package, {}, error);
  }
  /// One of the server's own faces (the demo faces): stored under its
  /// package's hash, or returned as it is when stored already. `durability`:
  /// made again at every start, they need not wait for the disk (a dozen
  /// flushes slow a start on a busy disk).
  std::optional<StoredAvatar> put_own_face(std::span<const std::uint8_t> package, std::string& error,
                                           Durability durability = Durability::unsynced);

  /// Deletes the avatar `asset` here and in the cluster's copy (the other
  /// nodes are told): its package, preview and photo. From now on it is
  /// `deleted`, and a preparation of it still running is thrown away.
  /// false if nothing was stored under it.
  bool remove(const std::string& asset);
  /// Drops this node's copy of an avatar deleted on another node.
  void forget(const std::string& asset);
  /// Deletes here (files and memory, not the cluster's copy, which expires
  /// by itself) the avatars last used before `cutoff`, except `keep` (the
  /// server's own faces); the ids it deleted (avatar_retention.hpp).
  std::vector<std::string> remove_unused_since(std::filesystem::file_time_type cutoff,
                                               const std::set<std::string>& keep);

  /// The avatar with id `asset`. A stored package of another format or
  /// generic face is handed to the repreparer when its photo is there (once;
  /// meanwhile the answer is being_prepared); never blocks on a preparation.
  AvatarLookup lookup(const std::string& asset);
  /// The avatar when it is found, else nullopt.
  std::optional<StoredAvatar> get(const std::string& asset) { return lookup(asset).avatar; }

  /// Who prepares out-of-date avatars again; none (the default) means this
  /// server cannot, and they are refused as out of date.
  void set_repreparer(AvatarRepreparer repreparer);
  /// The cluster's copy (set once, before the store is used by others).
  void set_replica(AvatarReplica replica) { replica_ = std::move(replica); }
  /// Where the files are: DIR/avatars (the saved looks are kept there too).
  const std::filesystem::path& directory() const { return directory_; }
  /// Every avatar id stored here, and one avatar's files: for a node that
  /// shares its avatars again after Redis lost them.
  std::vector<std::string> stored_assets() const;
  bool read_files(const std::string& asset, std::vector<std::uint8_t>& package, std::vector<std::uint8_t>& photo) const;
  /// The avatar `asset`, prepared again: `package` replaces its package under
  /// the same id. false and `error` if the package is invalid or cannot be
  /// written (the avatar is then refused as out of date until a restart).
  bool replace(const std::string& asset, std::span<const std::uint8_t> package, std::string& error);
  /// Preparing `asset` again failed; `why` says why, for a person.
  void preparation_failed(const std::string& asset, const std::string& why);

 private:
  std::filesystem::path file(const std::string& asset, const char* suffix) const;
  AvatarLookup load(const std::string& asset);
  /// Fetches `asset` from the cluster's copy into this store's directory.
  bool fetch_from_replica(const std::string& asset);
  AvatarLookup out_of_date(const std::string& asset, const std::string& why);
  std::optional<StoredAvatar> write_and_remember(const std::string& asset, std::span<const std::uint8_t> package,
                                                 const model::AvatarPackage& parsed, std::string& error,
                                                 Durability durability = Durability::synced);
  /// Removes `asset`'s files and memory here; whether any file was there.
  bool remove_here(const std::string& asset);
  /// `asset` was asked for and found: its package file's modification time
  /// becomes its last use, at most once an hour (a busy avatar costs no
  /// write per request).
  void note_use(const std::string& asset);
  void refuse(const std::string& asset, const AvatarLookup& refusal);

  std::filesystem::path directory_;
  Metrics& metrics_;
  std::mutex mutex_;
  std::map<std::string, StoredAvatar> cache_;
  std::map<std::string, AvatarLookup> refused_;  ///< stored but refused: damaged, or out of date for good
  std::set<std::string> preparing_;               ///< handed to the repreparer, not back yet
  std::set<std::string> deleted_;                 ///< deleted by their uploader since the start
  std::map<std::string, std::chrono::steady_clock::time_point> last_noted_;  ///< note_use's last write
  AvatarRepreparer repreparer_;
  AvatarReplica replica_;
};

/// Whether `text` has the form of an asset id (so it is safe in a path).
bool is_asset_id(std::string_view text);

}  // namespace fw::server
