#pragma once
// Binary range decoder, the mirror of RangeEncoder. It never reads outside
// its frame: bytes past the end read as zero (the encoder drops trailing
// zeros). It carries the frame's sticky error: the symbol decoders above it
// report a malformed number with fail(), keep going with harmless values,
// and the frame is checked once at its end.
#include <cstdint>
#include <span>

#include "adaptive_bit.hpp"
#include "fw/codec/codec.hpp"

namespace fw::codec {

class RangeDecoder {
 public:
  explicit RangeDecoder(std::span<const std::uint8_t> data);

  /// Decodes one bit with `model`'s probability and adapts the model.
  int decode(AdaptiveBit& model);
  /// Decodes `count` (0 .. 24) equiprobable bits, most significant first.
  std::uint32_t decode_raw(int count);

  /// Records the first error of the frame; later ones are ignored.
  void fail(DecodeError error);
  DecodeError error() const { return error_; }

 private:
  std::uint8_t next_byte();
  void normalise();

  std::span<const std::uint8_t> data_;
  std::size_t position_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint32_t code_ = 0;  ///< offset of the coded value above the interval's bottom
  DecodeError error_ = DecodeError::ok;
};

}  // namespace fw::codec
