#pragma once
// The ids a room hands its avatars. The codec spends 21 bits on an id
// (codec/FORMAT.md), so a room that only ever counted up would run out
// after 2^21 joins and then send frames nobody can read. Ids are therefore
// handed out again, but only after they rested for a quiet period since
// their avatar left: a client that still hears of the old face (a presence
// `left` and a `joined` crossing on a slow link) never takes a newcomer for
// it. Time is counted in the room's ticks, which never run ahead of the
// clock (a late room ticks less often, so its ids rest longer, not shorter).
//
// Ids go round in order (1, 2, ... space - 1, then 1 again), skipping the
// ones in use or resting, so an id comes back as late as possible. 0 is
// never handed out: it means "no avatar" (and, in a chat line, the server).
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace fw::server {

class AvatarIds {
 public:
  using Id = std::uint32_t;

  /// Ids 1 .. space - 1, each resting `quiet_ticks` after it is given back.
  AvatarIds(Id space, std::uint64_t quiet_ticks);

  /// A free id, or 0 when every id is in use or resting.
  Id take(std::uint64_t now_tick);
  /// `id`'s avatar left at `now_tick`: the id rests, then is free again.
  void give_back(Id id, std::uint64_t now_tick);
  /// Takes `id` itself (a room restored on another server keeps its
  /// avatars' ids); false if it is in use or outside the space.
  bool claim(Id id);
  /// `id` was taken but never shown to anyone: free at once.
  void cancel(Id id) { in_use_.erase(id); }

  std::size_t in_use() const { return in_use_.size(); }
  /// Ids that still rest at `now_tick`.
  std::size_t resting(std::uint64_t now_tick);
  Id space() const { return space_; }

 private:
  /// Forgets the rest of ids whose quiet period is over.
  void wake(std::uint64_t now_tick);

  Id space_;
  std::uint64_t quiet_ticks_;
  Id next_ = 1;
  std::unordered_set<Id> in_use_;
  std::unordered_set<Id> resting_;
  std::deque<std::pair<std::uint64_t, Id>> given_back_;  ///< (tick, id), oldest first
};

}  // namespace fw::server
