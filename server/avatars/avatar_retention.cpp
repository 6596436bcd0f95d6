#include "avatar_retention.hpp"

#include <spdlog/spdlog.h>

namespace fw::server {

AvatarSweeper::AvatarSweeper(AvatarStore& store, std::set<std::string> own_faces, std::uint32_t retention_days,
                             std::chrono::seconds interval)
    : store_(store),
      own_faces_(std::move(own_faces)),
      retention_days_(retention_days),
      retention_(retention_days),
      interval_(interval) {
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
  const auto removed = store_.remove_unused_since(*cutoff, own_faces_);
  if (!removed.empty())
    spdlog::info("deleted {} avatar(s) with their photos, unused for {} days (--avatar-retention-days)",
                 removed.size(), retention_days_);
}

}  // namespace fw::server
