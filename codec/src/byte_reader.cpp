#include "fw/codec/byte_reader.hpp"

#include <cstring>

namespace fw::codec {

std::uint8_t ByteReader::u8() {
  if (position_ >= data_.size()) {
    failed_ = true;
    return 0;
  }
  return data_[position_++];
}

std::uint16_t ByteReader::u16_le() {
  const std::uint16_t lo = u8();
  const std::uint16_t hi = u8();
  return static_cast<std::uint16_t>(lo | (hi << 8));
}

std::int16_t ByteReader::i16_le() { return static_cast<std::int16_t>(u16_le()); }

std::uint32_t ByteReader::u32_le() {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value |= static_cast<std::uint32_t>(u8()) << (8 * i);
  return failed_ ? 0 : value;  // no half-read value
}

float ByteReader::f32_le() {
  const std::uint32_t bits = u32_le();
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::uint32_t ByteReader::varint(std::size_t max_bytes) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < max_bytes && i < 5; ++i) {
    const std::uint8_t byte = u8();
    if (failed_) return 0;
    const std::uint32_t payload = byte & 0x7Fu;
    if (i == 4 && payload > 0x0F) break;  // would not fit 32 bits
    value |= payload << (7 * i);
    if ((byte & 0x80) == 0) {
      if (i > 0 && byte == 0) break;  // overlong: every value has exactly one encoding
      return value;
    }
  }
  // Longer than the field allows, overlong or too wide: the bytes were there.
  failed_ = true;
  bad_number_ = true;
  return 0;
}

std::span<const std::uint8_t> ByteReader::bytes(std::size_t count) {
  if (count > remaining()) {
    failed_ = true;
    position_ = data_.size();
    return {};
  }
  const auto view = data_.subspan(position_, count);
  position_ += count;
  return view;
}

}  // namespace fw::codec
