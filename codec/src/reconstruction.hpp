#pragma once
// The face as the decoder knows it between frames (FORMAT.md, "Prediction"):
// per channel a value in sub-steps, a velocity in sub-steps per tick and the
// ticks since its last update. The encoder keeps an identical copy, so every
// residual it sends is against what the viewer sees and errors never
// accumulate.
#include <algorithm>
#include <array>
#include <cstdint>

#include "channel_table.hpp"
#include "fw/codec/codec.hpp"

namespace fw::codec {

class Reconstruction {
 public:
  explicit Reconstruction(std::uint8_t max_extrapolation_ticks = 32)
      : ranges_(coded_ranges().data()), max_extrapolation_ticks_(max_extrapolation_ticks) {}

  /// Every channel at rest (0), still.
  void reset();
  /// Moves time forward by `ticks` (ages saturate at the extrapolation limit).
  void advance(std::uint32_t ticks);
  /// Channel `c` as coded, now, in grid steps: its value moved by its
  /// (damped) velocity for min(age, limit) ticks, clamped to the channel's
  /// coded range, rounded to the nearest step.
  std::int32_t shown(std::size_t c) const { return shown_after(c, 0); }
  /// The same, `extra_ticks` from now without further updates.
  /// (Inline: the encoder asks for every channel twice a tick, for every
  /// avatar and viewer.)
  std::int32_t shown_after(std::size_t c, std::uint32_t extra_ticks) const {
    const Channel& ch = channels_[c];
    const std::int64_t ticks = std::min<std::int64_t>(std::int64_t{ch.age} + extra_ticks, max_extrapolation_ticks_);
    const std::int64_t v = ch.damping == 0 ? ch.value + std::int64_t{ch.velocity} * ticks : glide(ch, ticks);
    const CodedRange range = ranges_[c];
    const std::int64_t clamped =
        std::clamp<std::int64_t>(v, std::int64_t{range.min} * kSubSteps, std::int64_t{range.max} * kSubSteps);
    return static_cast<std::int32_t>((clamped + kSubSteps / 2) >> kSubStepBits);  // nearest step, halves up
  }
  ChannelValues shown_all(std::uint32_t extra_ticks = 0) const;

  /// Channel `c` becomes `q` (grid steps, in its coded range) moving at
  /// `velocity_sub_steps` per tick with damping class `damping`, from now.
  void set(std::size_t c, std::int32_t q, std::int32_t velocity_sub_steps, int damping = 0);
  std::int32_t velocity(std::size_t c) const { return channels_[c].velocity; }
  int damping(std::size_t c) const { return channels_[c].damping; }
  /// Ticks since channel `c` was last set.
  std::uint32_t age(std::size_t c) const { return channels_[c].age; }
  std::uint8_t max_extrapolation_ticks() const { return max_extrapolation_ticks_; }
  /// Every channel stops where it is shown now (after a lost frame: the face
  /// holds still instead of moving on a velocity that may have changed).
  void freeze();

 private:
  struct Channel {
    std::int32_t value = 0;     ///< sub-steps
    std::int32_t velocity = 0;  ///< sub-steps per tick, at the last update
    std::uint8_t damping = 0;   ///< damping class, 0 .. kDampingClasses-1
    /// Ticks since the last update, saturating at the extrapolation limit
    /// (at most 255): a byte keeps a channel in 12 bytes, and the encoder
    /// reads every channel of every viewer's view each tick.
    std::uint8_t age = 0;
  };
  /// A damped channel's value after `ticks`, sub-steps, unclamped.
  static std::int64_t glide(const Channel& ch, std::int64_t ticks);

  std::array<Channel, kChannelCount> channels_{};
  const CodedRange* ranges_;  ///< coded_ranges(), looked up once
  std::uint8_t max_extrapolation_ticks_;
};

}  // namespace fw::codec
