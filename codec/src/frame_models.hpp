#pragma once
// Everything the frame syntax adapts to (FORMAT.md, "Contexts"): the binary
// models of every decision and the per-channel history their contexts are
// chosen by. Encoder and decoder hold identical copies; a key frame resets
// them, so a key frame decodes without any earlier frame.
#include <array>

#include "adaptive_bit.hpp"
#include "channel_table.hpp"
#include "fw/codec/codec.hpp"
#include "integer_coding.hpp"

namespace fw::codec {

struct FrameModels {
  IntegerModel tick_delta;
  AdaptiveBit level_changed;
  /// [group][whether the group was updated in the previous frame]
  std::array<std::array<AdaptiveBit, 2>, kChannelGroupCount> group_updated{};
  /// [channel][context]: see channel_update_context()
  std::array<std::array<AdaptiveBit, 12>, kChannelCount> channel_updated{};
  /// [group][whether predicted from the partner's residual]
  std::array<std::array<IntegerModel, 2>, kChannelGroupCount> residual{};
  std::array<std::array<IntegerModel, 2>, kChannelGroupCount> velocity{};
  /// [group][0, or 1 + the partner's class when predicted from the partner][tree node 1 .. 7]
  std::array<std::array<std::array<AdaptiveBit, kDampingClasses>, 1 + kDampingClasses>, kChannelGroupCount> damping{};
  /// Key frames: [group]
  std::array<AdaptiveBit, kChannelGroupCount> key_same_as_partner{};
  std::array<AdaptiveBit, kChannelGroupCount> key_nonzero{};

  /// History (not probabilities): whether each channel was updated the last
  /// time its group was, and whether each group was updated in the previous
  /// predicted frame (all false after a key frame).
  std::array<bool, kChannelCount> updated_last{};
  std::array<bool, kChannelGroupCount> group_updated_last{};

  /// Back to the state at a key frame's start.
  void reset() { *this = FrameModels{}; }
};

/// Which channel_updated context channel `c` uses: 0 .. 11 from whether it
/// was updated in the previous frame, whether it is active (shown value or
/// velocity not zero) and whether it has a partner updated in this frame
/// (none, not updated, updated).
int channel_update_context(const FrameModels& models, std::size_t c, bool active,
                           const std::array<bool, kChannelCount>& updated_now);

/// Damping class as kDampingBits bits, most significant first, each with
/// the model of its node in a binary tree (node 1, then 2 * node + bit).
void encode_damping(RangeEncoder& encoder, std::array<AdaptiveBit, kDampingClasses>& tree, int damping_class);
int decode_damping(RangeDecoder& decoder, std::array<AdaptiveBit, kDampingClasses>& tree);

}  // namespace fw::codec
