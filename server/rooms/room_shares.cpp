#include "room_shares.hpp"

#include <algorithm>

namespace fw::server {

RoomShareRefusal RoomShares::may_open(const std::string& address, const std::string& block, std::size_t open,
                                      std::size_t max_rooms) const {
  if (held_by_address(address) >= limits_.per_address) return RoomShareRefusal::address;
  const std::size_t block_holds = held_by_block(block);
  if (block_holds >= limits_.per_block) return RoomShareRefusal::block;
  // The last rooms wait for a network that holds none: whoever squats the
  // rest from a few blocks leaves them to everyone else.
  const std::size_t reserve = std::min(limits_.fresh_reserve, max_rooms);
  if (block_holds > 0 && open + reserve >= max_rooms) return RoomShareRefusal::reserve;
  return RoomShareRefusal::none;
}

void RoomShares::opened(const std::string& room, const std::string& address, const std::string& block) {
  if (!openers_.emplace(room, Opener{address, block}).second) return;
  ++by_address_[address];
  ++by_block_[block];
}

void RoomShares::closed(const std::string& room) {
  const auto it = openers_.find(room);
  if (it == openers_.end()) return;
  drop(by_address_, it->second.address);
  drop(by_block_, it->second.block);
  openers_.erase(it);
}

}  // namespace fw::server
