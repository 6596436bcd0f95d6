#pragma once
// Reads the range-coded part of key and predicted frames into a
// CodingState, the mirror of frame_writer. Every number is range checked;
// every loop is bounded by the channel table, whatever the bytes.
#include <cstdint>
#include <span>

#include "coding_state.hpp"
#include "fw/codec/codec.hpp"

namespace fw::codec {

/// Decodes `payload` (the bytes after the first byte and the sequence
/// number) of a frame of `type` (key or predicted) into `state`. On an error
/// `state` is left half-updated: the caller decodes into a copy.
/// @param[out] tick_delta  ticks since the stream's previous frame
DecodeError read_frame_payload(CodingState& state, FrameType type, std::span<const std::uint8_t> payload,
                               std::uint32_t& tick_delta);

}  // namespace fw::codec
