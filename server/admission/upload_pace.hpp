#pragma once
// Whether an upload's body still comes fast enough to keep its place. A
// body that trickles in holds a connection, its bytes and an upload's turn
// while sending next to nothing: sixteen bodies dribbled a byte a second
// once kept every other upload out. Once the body has started, every
// window of `window` must bring `min_bytes_per_second * window` bytes; the
// first window is free (a connection's slow start, a phone waking its
// radio). A body that keeps the pace takes as long as it needs, so a large
// photo on a slow link is never cut off by a fixed deadline.
//
// A decision without sockets: the time is passed in (HttpSession records
// what arrived and asks when the pace would be missed if nothing more came).
#include <chrono>
#include <cstddef>
#include <deque>

namespace fw::server {

class UploadPace {
 public:
  using Clock = std::chrono::steady_clock;

  /// `min_bytes_per_second` 0: no pace is required (never too slow).
  UploadPace(std::size_t min_bytes_per_second, Clock::duration window, Clock::time_point start);

  /// `total` body bytes have arrived by `now` (the running total).
  void record(Clock::time_point now, std::size_t total);
  /// Whether the body missed the pace by `now`.
  bool too_slow(Clock::time_point now) const { return now >= deadline(); }
  /// When the body misses the pace if nothing more arrives; Clock's max
  /// when no pace is required.
  Clock::time_point deadline() const;

  std::size_t bytes_per_window() const { return bytes_per_window_; }

 private:
  struct Sample {
    Clock::time_point at;
    std::size_t total;
  };
  Clock::duration window_;
  Clock::time_point start_;
  std::size_t bytes_per_window_;
  std::size_t total_ = 0;
  /// When the running total grew, oldest first; those a window behind the
  /// newest are dropped (deadline() needs none older).
  std::deque<Sample> samples_;
};

}  // namespace fw::server
