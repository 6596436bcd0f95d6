#pragma once
// Who opened a server's rooms, by address and by network block
// (address_group()), and whether one more may open. A creation rate per
// address alone let 40 addresses take all 200 rooms of a server in a
// quarter of a second, and then nobody could open one. So an address holds
// at most `per_address` of the rooms it opened at once, its block at most
// `per_block`, and the last `fresh_reserve` rooms open only for someone
// whose block holds none. A room counts against whoever opened it until it
// closes (its last person left, or was let go for neither sending nor
// reading). Not thread-safe: RoomRegistry holds its lock around it.
#include <cstddef>
#include <map>
#include <string>

namespace fw::server {

struct RoomShareLimits {
  std::size_t per_address = 5;
  std::size_t per_block = 20;
  /// Rooms that only an address whose block holds none may open.
  std::size_t fresh_reserve = 100;
};

enum class RoomShareRefusal { none, address, block, reserve };

class RoomShares {
 public:
  explicit RoomShares(RoomShareLimits limits) : limits_(limits) {}

  /// Whether `address` in `block` may open one more room while `open` of
  /// `max_rooms` are open (the caller checks `max_rooms` itself).
  RoomShareRefusal may_open(const std::string& address, const std::string& block, std::size_t open,
                            std::size_t max_rooms) const;
  void opened(const std::string& room, const std::string& address, const std::string& block);
  /// The room closed (nothing if it was not counted: the lobby, a bridge).
  void closed(const std::string& room);

  std::size_t held_by_address(const std::string& address) const { return count(by_address_, address); }
  std::size_t held_by_block(const std::string& block) const { return count(by_block_, block); }
  const RoomShareLimits& limits() const { return limits_; }

 private:
  static std::size_t count(const std::map<std::string, std::size_t>& counts, const std::string& key) {
    const auto it = counts.find(key);
    return it == counts.end() ? 0 : it->second;
  }
  static void drop(std::map<std::string, std::size_t>& counts, const std::string& key) {
    const auto it = counts.find(key);
    if (it != counts.end() && --it->second == 0) counts.erase(it);
  }

  RoomShareLimits limits_;
  struct Opener {
    std::string address, block;
  };
  std::map<std::string, Opener> openers_;  ///< room -> who opened it
  std::map<std::string, std::size_t> by_address_, by_block_;
};

}  // namespace fw::server
