#pragma once
// The normative numbers of FaceParams schema 2 beyond the public table:
// channel groups, the quantiser shift of each group at each quality level,
// and the tolerances the encoder aims for (FORMAT.md, "Channels" and
// "Quality levels").
#include <array>
#include <cstddef>
#include <cstdint>

#include "fw/codec/codec.hpp"

namespace fw::codec {

/// Channels [first, first + count) form one group (groups are contiguous).
struct GroupSpan {
  std::size_t first;
  std::size_t count;
};
const std::array<GroupSpan, kChannelGroupCount>& group_spans();

inline std::size_t group_index(ChannelGroup g) { return static_cast<std::size_t>(g); }

/// Quantiser shift s of each group at each quality level: residuals and key
/// values are coded in units of 2^s grid steps, velocities in units of
/// 2^s / 4 grid steps per tick. Normative: the decoder uses it.
int group_shift(int level, std::size_t group);


/// Sub-steps per grid step in the decoder's reconstruction: values and
/// velocities carry 8 fractional bits so that slow and decaying velocities
/// keep their precision over many ticks.
inline constexpr int kSubStepBits = 8;
inline constexpr std::int32_t kSubSteps = 1 << kSubStepBits;
/// A velocity unit at shift s is (kVelocityUnitSubSteps << s) sub-steps per
/// tick: a quarter step per tick at shift 0.
inline constexpr std::int32_t kVelocityUnitSubSteps = kSubSteps / 4;

/// Velocity damping classes: 0 keeps the velocity (linear motion); class d
/// (1 .. 7) takes (|velocity| * kDampingNumerator[d]) >> 6 off it every tick,
/// so the channel glides exponentially toward a rest point (time constants
/// of about 21 down to 4 ticks), as a head does at the end of a gaze shift.
inline constexpr int kDampingClasses = 8;
inline constexpr int kDampingBits = 3;
inline constexpr std::int64_t kDampingNumerator[kDampingClasses] = {0, 3, 4, 6, 8, 10, 12, 16};
/// One tick of damping: the integer recurrence every decoder computes. At
/// least one sub-step goes each tick, so a damped velocity reaches 0.
constexpr std::int64_t damp(std::int64_t velocity, int damping_class) {
  if (damping_class == 0 || velocity == 0) return velocity;
  const std::int64_t magnitude = velocity >= 0 ? velocity : -velocity;
  std::int64_t cut = (magnitude * kDampingNumerator[damping_class]) >> 6;
  if (cut == 0) cut = 1;
  return velocity >= 0 ? velocity - cut : velocity + cut;
}

/// A channel's values as coded: the field's range, or for a channel with a
/// base the sum of both ranges.
struct CodedRange {
  std::int32_t min;
  std::int32_t max;
};
CodedRange coded_range(std::size_t channel);
/// Every channel's coded range (what coded_range() reads).
const std::array<CodedRange, kChannelCount>& coded_ranges();

/// One value per channel as coded (an eye plus its base, the head).
using ChannelValues = std::array<std::int32_t, kChannelCount>;
/// The field values a viewer gets from coded values: a channel with a base
/// minus its base, clamped to the field's range.
QuantisedParams fields_from_coded(const ChannelValues& coded);

/// Largest |velocity| a channel may have, in sub-steps per tick: its whole
/// coded range in one tick.
std::int32_t max_velocity(std::size_t channel);

/// Frames end with these check bits (4 equiprobable bits, all ones).
inline constexpr int kCheckBitCount = 4;
inline constexpr std::uint32_t kCheckBits = 0xF;

/// Tick deltas are 1 .. kMaxTickDelta.
inline constexpr std::uint32_t kMaxTickDelta = 1u << 16;

/// Bits of a quality level in a frame.
inline constexpr int kLevelBits = 3;

}  // namespace fw::codec
