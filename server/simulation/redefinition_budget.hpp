#pragma once
// How many bytes of unit morphs (PROTOCOL.md 5.17) a room's people may make
// every client receive. Each redefinition sends its avatar's whole set (up
// to about 15 KB) to everyone in the room, ahead of their faces' frames;
// counted per person, people on many addresses could together fill a 9.6
// kbit/s link with sets and starve it of faces. Counted per room, as a token
// bucket in bytes, the sets take at most a share of any link in the long
// run, whoever sends them.
#include <cstddef>
#include <optional>

namespace fw::server {

class RedefinitionBudget {
 public:
  /// 200 bytes a second: 1.6 kbit/s, a sixth of the slowest link the
  /// service supports (9.6 kbit/s). A burst of one largest set.
  static constexpr double kBytesPerSecond = 200;
  static constexpr double kBurstBytes = 16 * 1024;

  /// Takes `bytes` at room time `now_s` (seconds, never decreasing): nullopt
  /// when taken, else the seconds until they could be.
  std::optional<double> take(std::size_t bytes, double now_s);

 private:
  double tokens_ = kBurstBytes;
  double last_s_ = 0;
};

}  // namespace fw::server
