#pragma once
// Rate control for one encoder (FORMAT.md, "Rate control"; not normative):
// a leaky bucket that drains at the target rate and refuses frames that
// would overflow it (the encoder then skips the tick, which lowers the frame
// rate), and a quality level that follows the bucket's fill and the recent
// spending (coarser when the budget is tight, finer when bits are left).
#include <cstddef>

namespace fw::codec {

class RateController {
 public:
  /// @param[in] target_bps    budget, bits per second (> 0)
  /// @param[in] tick_rate_hz  ticks per second
  /// @param[in] min_level, max_level  quality levels allowed, 0 .. 7
  RateController(double target_bps, int tick_rate_hz, int min_level, int max_level);

  void set_target_bps(double target_bps);
  /// Once per tick, before the encoder decides: drains the bucket, moves the
  /// level if the spending asks for it.
  void on_tick();
  /// Whether a frame of `bits` may go out now: it fits in the bucket, or the
  /// bucket is empty (so a frame larger than the bucket still goes out, and
  /// the bucket then makes the next ones wait until it is paid for). An
  /// urgent frame (a channel far beyond its tolerance) may also use the
  /// reserve of half a bucket more; the level then goes coarser.
  bool allows(double bits, bool urgent = false) const;
  /// A frame went out. `optional_bits` of its `bits` carried optional
  /// channels (the correctives, sent on spare budget only): they fill the
  /// bucket like the rest but do not count in the spending that sets the
  /// level, so that they never make the level coarser for the others.
  void on_frame_sent(double bits, bool key, double optional_bits = 0);

  int level() const { return level_; }
  /// The spending over the last seconds for the budget (optional bits left
  /// out), or the bucket's fill for 3/4 of its capacity, whichever is
  /// higher: above 0.95 the level goes coarser, under 0.75 finer.
  double pressure() const;

  /// Ticks between key frames in a loss-tolerant stream: key frames take
  /// about an eighth of the budget, come at most every 2 s and at least
  /// every `max_ticks`.
  int key_interval_ticks(int max_ticks) const;

  double bucket_bits() const { return bucket_bits_; }
  double capacity_bits() const { return capacity_bits_; }
  double bits_per_tick() const { return bits_per_tick_; }

 private:
  int tick_rate_hz_;
  int min_level_;
  int max_level_;
  int level_;
  double bits_per_tick_ = 0;
  double capacity_bits_ = 0;
  double bucket_bits_ = 0;
  double average_bits_per_tick_ = 0;  ///< exponential average over about 2 s
  double spent_this_tick_ = 0;
  int ticks_since_level_change_ = 0;
  double last_key_bits_ = 0;
};

}  // namespace fw::codec
