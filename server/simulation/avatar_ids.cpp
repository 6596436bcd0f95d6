#include "avatar_ids.hpp"

#include <algorithm>

namespace fw::server {

AvatarIds::AvatarIds(Id space, std::uint64_t quiet_ticks) : space_(std::max<Id>(space, 2)), quiet_ticks_(quiet_ticks) {}

void AvatarIds::wake(std::uint64_t now_tick) {
  while (!given_back_.empty() && now_tick - given_back_.front().first >= quiet_ticks_) {
    resting_.erase(given_back_.front().second);
    given_back_.pop_front();
  }
}

std::size_t AvatarIds::resting(std::uint64_t now_tick) {
  wake(now_tick);
  return resting_.size();
}

AvatarIds::Id AvatarIds::take(std::uint64_t now_tick) {
  wake(now_tick);
  // Every id busy: say so at once instead of going round them all.
  if (in_use_.size() + resting_.size() >= space_ - 1) return 0;
  // At most in_use + resting ids are skipped before a free one.
  for (;;) {
    const Id id = next_;
    next_ = next_ + 1 >= space_ ? 1 : next_ + 1;
    if (in_use_.count(id) || resting_.count(id)) continue;
    in_use_.insert(id);
    return id;
  }
}

void AvatarIds::give_back(Id id, std::uint64_t now_tick) {
  if (in_use_.erase(id) == 0) return;
  wake(now_tick);
  if (quiet_ticks_ == 0) return;
  resting_.insert(id);
  given_back_.emplace_back(now_tick, id);
}

bool AvatarIds::claim(Id id) {
  if (id == 0 || id >= space_ || in_use_.count(id)) return false;
  resting_.erase(id);  // its rest is over: it is the same avatar's again
  in_use_.insert(id);
  return true;
}

}  // namespace fw::server
