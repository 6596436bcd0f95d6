#pragma once
// The saved looks of every avatar (saved_looks.hpp), beside the avatar's
// files: DIR/avatars/ID.looks, written whole (durable_file.hpp) and deleted
// with the avatar (AvatarStore removes it with the package, whether its
// uploader deletes it, another node did, or the retention sweep does).
// In a cluster the cluster's copy (LookReplica: a Redis hash per avatar)
// is what every node reads and changes, so that a look saved on one node
// plays on all; the file is then this node's copy of the whole set, read
// (with a warning) while Redis does not answer. Thread-safe; every call
// may block on the disk or on Redis, so none is made on a room's strand or
// on the I/O loop.
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "saved_looks.hpp"

namespace fw::server {

/// The cluster's copy of the looks (cluster_node_avatars.cpp). Blocking.
struct LookReplica {
  /// An avatar's looks; nullopt when Redis does not answer.
  std::function<std::optional<std::vector<SavedLook>>(const std::string& asset)> list;
  /// Saves or replaces one look; false when Redis does not answer.
  std::function<bool(const std::string& asset, const SavedLook& look)> put;
  /// Deletes one look; false when Redis does not answer.
  std::function<bool(const std::string& asset, const std::string& name)> remove;
};

/// What became of a change to an avatar's looks.
enum class LookChange {
  done,
  unknown_look,  ///< a deletion of a name the avatar has no look under
  full,          ///< a new name past kMaxLooksPerAvatar
  failed,        ///< the disk refused (the message says so)
};

class LookStore {
 public:
  /// `directory`: the avatar store's (AvatarStore::directory()).
  explicit LookStore(std::filesystem::path directory) : directory_(std::move(directory)) {}

  /// The looks of `asset`, by name.
  std::vector<SavedLook> list(const std::string& asset);
  /// The look `name` of `asset`, if it has one.
  std::optional<SavedLook> find(const std::string& asset, const std::string& name);
  /// Saves `look` (its name and script already checked), replacing one of
  /// the same name; `error` says what to do when it is not `done`.
  LookChange put(const std::string& asset, const SavedLook& look, std::string& error);
  LookChange remove(const std::string& asset, const std::string& name, std::string& error);

  /// The cluster's copy (set once, before the store is used by others).
  void set_replica(LookReplica replica) { replica_ = std::move(replica); }
  /// This node's own copy of `asset`'s looks (its file): for a node that
  /// shares them again after Redis lost them.
  std::vector<SavedLook> read_here(const std::string& asset) const;

 private:
  /// The looks as the cluster has them, or this node's file.
  std::vector<SavedLook> current(const std::string& asset);
  bool write_here(const std::string& asset, const std::vector<SavedLook>& looks, std::string& error);

  std::filesystem::path directory_;
  std::mutex mutex_;  ///< one change at a time: each reads the set, changes it and writes it back
  LookReplica replica_;
};

}  // namespace fw::server
