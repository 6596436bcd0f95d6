#pragma once
// Byte-aligned input with a sticky error flag: a read past the end returns 0
// and marks the reader failed, so a parser reads its fields and checks
// failed() once instead of after every field. Little-endian. Public so that
// every parser of outside bytes (the codec's messages, avatar/behavior's
// scene files) reads through the same bounds checks.
#include <cstddef>
#include <cstdint>
#include <span>

namespace fw::codec {

class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> data) : data_(data) {}

  std::uint8_t u8();
  std::uint16_t u16_le();
  std::int16_t i16_le();
  std::uint32_t u32_le();
  float f32_le();
  /// Unsigned LEB128 of at most `max_bytes` bytes (1 .. 5); a longer one, an
  /// overlong one (a final 0x00 byte after the first), or one whose value
  /// does not fit 32 bits, fails the reader and marks it bad_number().
  std::uint32_t varint(std::size_t max_bytes = 5);
  /// The next `count` bytes as a view; fails (and returns an empty view) if
  /// fewer remain.
  std::span<const std::uint8_t> bytes(std::size_t count);

  bool failed() const { return failed_; }
  /// Whether it failed on a number written wrongly rather than on bytes
  /// running out: a sender's bug or forgery, not a cut message, and told
  /// apart so that the error names the right cause.
  bool bad_number() const { return bad_number_; }
  std::size_t position() const { return position_; }
  std::size_t remaining() const { return data_.size() - position_; }

 private:
  std::span<const std::uint8_t> data_;
  std::size_t position_ = 0;
  bool failed_ = false;
  bool bad_number_ = false;
};

}  // namespace fw::codec
