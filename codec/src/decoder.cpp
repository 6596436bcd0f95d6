// Decoder: frame header, sequence numbers and the key-frame state machine
// around frame_reader (FORMAT.md, "Decoding", "Loss-tolerant streams").
#include <cassert>

#include "channel_table.hpp"
#include "coding_state.hpp"
#include "frame_reader.hpp"
#include "prefetch.hpp"
#include "fw/codec/codec.hpp"

namespace fw::codec {

struct Decoder::State {
  explicit State(const StreamOptions& o) : options(o), coding(o.max_extrapolation_ticks) {}

  StreamOptions options;
  CodingState coding;
  bool needs_key = true;
  bool has_sequence = false;
  std::uint8_t last_sequence = 0;
  std::uint64_t tick = 0;
  std::uint64_t frames = 0;

  // A frame the encoder sent could not be applied: from here on the
  // decoder's state may differ from the encoder's, so the face holds still
  // and only a key frame is accepted.
  DecodeError lose_sync(DecodeError error) {
    coding.reconstruction.freeze();
    needs_key = true;
    return error;
  }
};

Decoder::Decoder(const StreamOptions& options) : state_(std::make_unique<State>(options)) {}
Decoder::~Decoder() = default;
Decoder::Decoder(Decoder&&) noexcept = default;
Decoder& Decoder::operator=(Decoder&&) noexcept = default;

DecodeError Decoder::decode(std::span<const std::uint8_t> frame) {
  State& s = *state_;
  if (frame.empty()) return s.lose_sync(DecodeError::empty_frame);
  if (frame.size() > kMaxFrameBytes) return s.lose_sync(DecodeError::frame_too_large);
  if ((frame[0] >> 4) != kFormatVersion) return s.lose_sync(DecodeError::unsupported_version);
  const std::uint8_t type_bits = frame[0] & 0x0F;
  if (type_bits > static_cast<std::uint8_t>(FrameType::resync_request)) return s.lose_sync(DecodeError::unknown_frame_type);
  const auto type = static_cast<FrameType>(type_bits);
  if (type != FrameType::key && type != FrameType::predicted) return s.lose_sync(DecodeError::wrong_frame_type);

  std::size_t header_bytes = 1;
  if (s.options.loss_tolerant) {
    if (frame.size() < 2) return s.lose_sync(DecodeError::truncated);
    const std::uint8_t sequence = frame[1];
    header_bytes = 2;
    if (s.needs_key) {
      // Track the sender while waiting, so that the key frame is never
      // mistaken for a late one however long the wait.
      s.last_sequence = sequence;
      s.has_sequence = true;
      if (type == FrameType::predicted) return DecodeError::awaiting_key_frame;
    } else if (s.has_sequence) {
      const auto ahead = static_cast<std::uint8_t>(sequence - static_cast<std::uint8_t>(s.last_sequence + 1));
      if (ahead >= 128) return DecodeError::stale_frame;  // a duplicate or late frame: state untouched
      s.last_sequence = sequence;
      if (ahead != 0 && type == FrameType::predicted) return s.lose_sync(DecodeError::sequence_gap);
    }
    s.last_sequence = sequence;
    s.has_sequence = true;
  } else if (s.needs_key && type == FrameType::predicted) {
    return DecodeError::awaiting_key_frame;
  }

  // Read in place, not into a copy of the whole coding state (its models
  // are some 5 KB, copied twice a frame: most of what decoding cost). A
  // frame refused halfway leaves models and level half-read, which nothing
  // reads again: the decoder waits for a key frame, which resets the models
  // and sets the level and every channel. The face it shows meanwhile is
  // the one before the frame, so that much is kept aside. The state's lines
  // are asked for together first: one decoder among thousands finds none
  // of them in the cache, and fetched one by one where the frame needs them
  // they cost more than the copy did (prefetch.hpp).
  prefetch_whole(s.coding);
  const Reconstruction shown_before = s.coding.reconstruction;
  std::uint32_t tick_delta = 0;
  const DecodeError error = read_frame_payload(s.coding, type, frame.subspan(header_bytes), tick_delta);
  if (error != DecodeError::ok) {
    s.coding.reconstruction = shown_before;
    return s.lose_sync(error);
  }
  s.needs_key = false;
  s.tick += tick_delta;
  ++s.frames;
  return DecodeError::ok;
}

QuantisedParams Decoder::quantised(std::uint32_t ticks_after) const {
  return fields_from_coded(state_->coding.reconstruction.shown_all(ticks_after));
}

FaceParams Decoder::face(std::uint32_t ticks_after) const { return dequantise(quantised(ticks_after)); }

bool Decoder::needs_key_frame() const { return state_->needs_key; }
std::uint64_t Decoder::tick() const { return state_->tick; }
std::uint64_t Decoder::frames_decoded() const { return state_->frames; }

}  // namespace fw::codec
