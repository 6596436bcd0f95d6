#include "fw/codec/byte_writer.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(ByteWriter, WritesLittleEndianFields) {
  std::vector<std::uint8_t> out = {0xAA};  // appends, never clears
  ByteWriter w(out);
  w.u8(1);
  w.u16_le(0x1234);
  w.i16_le(-2);
  w.f32_le(1.0f);
  w.u32_le(0x12345678u);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0xAA, 1, 0x34, 0x12, 0xFE, 0xFF, 0x00, 0x00, 0x80, 0x3F, 0x78, 0x56, 0x34,
                                            0x12}));
}

TEST(ByteWriter, WritesMinimalLeb128Varints) {
  for (const auto& [value, expected] : std::vector<std::pair<std::uint32_t, std::vector<std::uint8_t>>>{
           {0, {0x00}}, {127, {0x7F}}, {128, {0x80, 0x01}}, {300, {0xAC, 0x02}}, {0xFFFFFFFFu, {0xFF, 0xFF, 0xFF, 0xFF, 0x0F}}}) {
    std::vector<std::uint8_t> out;
    ByteWriter(out).varint(value);
    EXPECT_EQ(out, expected) << value;
    EXPECT_EQ(varint_size(value), expected.size()) << value;
  }
}

}  // namespace
}  // namespace fw::codec
