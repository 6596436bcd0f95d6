#include "avatar_retention.hpp"

#include <set>

#include <spdlog/spdlog.h>

namespace fw::server {

AvatarSweeper::AvatarSweeper(ServerContext& context, std::chrono::seconds interval)
    : context_(context), retention_(context.config.avatar_retention_days), interval_(interval) {
  if (!retention_.forever()) thread_ = std::thread([this] { run(); });
}

AvatarSweeper::~AvatarSweeper() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void AvatarSweeper::run() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    lock.unlock();
    sweep();
    lock.lock();
    wake_.wait_for(lock, interval_, [this] { return stopping_; });
  }
}

void AvatarSweeper::sweep() {
  const auto cutoff = retention_.cutoff(AvatarRetention::FileTime::clock::now());
  if (!cutoff) return;
  std::set<std::string> own_faces;
  for (const StoredAvatar& face : context_.demo_avatars) own_faces.insert(face.asset);
  const auto removed = context_.store->remove_unused_since(*cutoff, own_faces);
  if (!removed.empty())
    spdlog::info("deleted {} avatar(s) with their photos, unused for {} days (--avatar-retention-days)",
                 removed.size(), context_.config.avatar_retention_days);
}

}  // namespace fw::server
