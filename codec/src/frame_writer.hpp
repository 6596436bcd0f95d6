#pragma once
// Writes key and predicted frames (FORMAT.md, "Key frames", "Predicted
// frames") and applies each to the encoder's CodingState exactly as the
// decoder will apply it.
#include <array>
#include <cstdint>
#include <vector>

#include "channel_table.hpp"
#include "coding_state.hpp"
#include "fw/codec/codec.hpp"
#include "model_journal.hpp"

namespace fw::codec {

/// What the encoder wants a frame to say.
struct FrameDecision {
  FrameType type = FrameType::predicted;  ///< key or predicted
  std::uint32_t tick_delta = 1;           ///< ticks since the stream's previous frame, 1 .. 65536
  int level = 0;                          ///< quality level, 0 .. kMaxQualityLevel
  /// Predicted frames: which channels to update (key frames update all).
  std::array<bool, kChannelCount> update{};
  /// Values wanted, coded (an eye plus its base), in grid steps within each
  /// channel's coded range; the frame carries them rounded to the level's units.
  ChannelValues target{};
  /// Velocities wanted, sub-steps per tick; rounded to the level's units and
  /// limited to max_velocity().
  std::array<std::int32_t, kChannelCount> velocity{};
  /// Damping class wanted for each moving channel (0 .. kDampingClasses-1).
  std::array<int, kChannelCount> damping{};
};

/// Appends the frame to `out` and updates `state` to what the decoder will
/// hold after it. `sequence` is written only in loss-tolerant streams.
/// `journal`, when given, notes every adaptive model the frame changes (a
/// predicted frame's changes can then be undone; a key frame resets them all).
void write_frame(CodingState& state, const StreamOptions& options, std::uint8_t sequence,
                 const FrameDecision& decision, std::vector<std::uint8_t>& out, ModelJournal* journal = nullptr);

/// First byte of a frame of `type`.
constexpr std::uint8_t first_byte(FrameType type) {
  return static_cast<std::uint8_t>((kFormatVersion << 4) | static_cast<std::uint8_t>(type));
}

}  // namespace fw::codec
