#include "fw/codec/byte_writer.hpp"

#include <bit>
#include <cstring>

namespace fw::codec {

void ByteWriter::u16_le(std::uint16_t value) {
  out_.push_back(static_cast<std::uint8_t>(value & 0xFF));
  out_.push_back(static_cast<std::uint8_t>(value >> 8));
}

void ByteWriter::i16_le(std::int16_t value) { u16_le(static_cast<std::uint16_t>(value)); }

void ByteWriter::u32_le(std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out_.push_back(static_cast<std::uint8_t>((value >> (8 * i)) & 0xFF));
}

void ByteWriter::f32_le(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);  // the IEEE-754 pattern, independent of host order in u32_le
  u32_le(bits);
}

void ByteWriter::varint(std::uint32_t value) {
  while (value >= 0x80) {
    out_.push_back(static_cast<std::uint8_t>((value & 0x7F) | 0x80));
    value >>= 7;
  }
  out_.push_back(static_cast<std::uint8_t>(value));
}

void ByteWriter::bytes(std::span<const std::uint8_t> data) { out_.insert(out_.end(), data.begin(), data.end()); }

std::size_t varint_size(std::uint32_t value) {
  std::size_t n = 1;
  while (value >= 0x80) {
    value >>= 7;
    ++n;
  }
  return n;
}

}  // namespace fw::codec
