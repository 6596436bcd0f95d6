#include "range_decoder.hpp"

#include <cassert>

namespace fw::codec {

RangeDecoder::RangeDecoder(std::span<const std::uint8_t> data) : data_(data) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next_byte();
  // The coded value lies below 2^32 - 1, so a valid code starts inside the
  // interval; anything else is corrupt (and would break the invariant
  // code < range that keeps decoding well defined).
  if (code_ >= range_) fail(DecodeError::check_failed);
}

std::uint8_t RangeDecoder::next_byte() { return position_ < data_.size() ? data_[position_++] : 0; }

void RangeDecoder::normalise() {
  while (range_ < (1u << 24)) {
    range_ <<= 8;
    code_ = (code_ << 8) | next_byte();
  }
}

int RangeDecoder::decode(AdaptiveBit& model) {
  const std::uint32_t bound = (range_ >> kProbabilityBits) * model.p0;
  int bit = 0;
  if (code_ < bound) {
    range_ = bound;
  } else {
    code_ -= bound;
    range_ -= bound;
    bit = 1;
  }
  model.update(bit);
  normalise();
  return bit;
}

std::uint32_t RangeDecoder::decode_raw(int count) {
  assert(count >= 0 && count <= 24);
  std::uint32_t value = 0;
  for (int i = 0; i < count; ++i) {
    const std::uint32_t half = range_ >> 1;
    std::uint32_t bit = 0;
    if (code_ < half) {
      range_ = half;
    } else {
      code_ -= half;
      range_ -= half;
      bit = 1;
    }
    value = (value << 1) | bit;
    normalise();
  }
  return value;
}

void RangeDecoder::fail(DecodeError error) {
  if (error_ == DecodeError::ok) error_ = error;
}

}  // namespace fw::codec
