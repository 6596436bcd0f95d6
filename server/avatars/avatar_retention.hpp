#pragma once
// How long the store keeps avatars and their photos (--avatar-retention-days):
// until they were not used for that long. A use is an upload, a hello that
// wears the avatar, or a download of its package; the store keeps the last
// one as its package file's modification time (AvatarStore::note_use), so
// it survives restarts and needs no file of its own. The server's own faces
// are never swept. In a cluster each node sweeps its own copies, and Redis
// lets its copy expire after the same time without a use on any node.
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "avatar_store.hpp"

namespace fw::server {

class AvatarRetention {
 public:
  using FileTime = std::filesystem::file_time_type;

  /// `days` without a use; 0 keeps avatars until their uploader deletes them.
  explicit AvatarRetention(std::uint32_t days) : period_(std::chrono::hours(24) * days) {}

  bool forever() const { return period_.count() == 0; }
  /// Avatars last used before this are swept at `now`; nullopt: none ever is.
  std::optional<FileTime> cutoff(FileTime now) const {
    if (forever()) return std::nullopt;
    return now - period_;
  }
  std::chrono::seconds period() const { return period_; }

 private:
  std::chrono::seconds period_;
};

/// Sweeps the store at start and then every `interval` on a thread of its
/// own (file deletions only; nothing waits for it), until destroyed. Never
/// sweeps `own_faces`, the server's own (the demo faces).
class AvatarSweeper {
 public:
  AvatarSweeper(AvatarStore& store, std::set<std::string> own_faces, std::uint32_t retention_days,
                std::chrono::seconds interval = std::chrono::hours(1));
  ~AvatarSweeper();
  AvatarSweeper(const AvatarSweeper&) = delete;
  AvatarSweeper& operator=(const AvatarSweeper&) = delete;

 private:
  void run();
  void sweep();

  AvatarStore& store_;
  const std::set<std::string> own_faces_;
  const std::uint32_t retention_days_;
  AvatarRetention retention_;
  std::chrono::seconds interval_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace fw::server
