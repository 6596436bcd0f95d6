#pragma once
// Byte-aligned output for the parts of the format that are not range coded:
// first bytes, sequence numbers, stream headers, room frame entries; and for
// avatar/behavior's scene files. Little-endian; ByteReader reads it back.
#include <cstdint>
#include <span>
#include <vector>

namespace fw::codec {

/// Appends to a caller's vector (which it does not clear).
class ByteWriter {
 public:
  explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}

  void u8(std::uint8_t value) { out_.push_back(value); }
  void u16_le(std::uint16_t value);
  void i16_le(std::int16_t value);
  void u32_le(std::uint32_t value);
  void f32_le(float value);
  /// Unsigned LEB128: 7 bits per byte, low bits first, high bit = "more".
  void varint(std::uint32_t value);
  void bytes(std::span<const std::uint8_t> data);

 private:
  std::vector<std::uint8_t>& out_;
};

/// Bytes varint() writes for `value` (1 .. 5).
std::size_t varint_size(std::uint32_t value);

}  // namespace fw::codec
