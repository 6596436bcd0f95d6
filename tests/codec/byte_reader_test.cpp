#include "fw/codec/byte_reader.hpp"

#include <vector>

#include <gtest/gtest.h>

#include "fw/codec/byte_writer.hpp"

namespace fw::codec {
namespace {

TEST(ByteReader, ReadsWhatTheWriterWrote) {
  std::vector<std::uint8_t> bytes;
  ByteWriter w(bytes);
  w.u8(7);
  w.u16_le(0xBEEF);
  w.i16_le(-1234);
  w.f32_le(-0.125f);
  w.u32_le(0xDEADBEEFu);
  w.varint(0);
  w.varint(1u << 20);
  ByteReader r(bytes);
  EXPECT_EQ(r.u8(), 7);
  EXPECT_EQ(r.u16_le(), 0xBEEF);
  EXPECT_EQ(r.i16_le(), -1234);
  EXPECT_EQ(r.f32_le(), -0.125f);
  EXPECT_EQ(r.u32_le(), 0xDEADBEEFu);
  EXPECT_EQ(r.varint(), 0u);
  EXPECT_EQ(r.varint(), 1u << 20);
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.remaining(), 0u);
}

TEST(ByteReader, ReadsU32LittleEndian) {
  const std::vector<std::uint8_t> bytes = {0x78, 0x56, 0x34, 0x12, 0xFF, 0xFF, 0xFF};
  ByteReader r(bytes);
  EXPECT_EQ(r.u32_le(), 0x12345678u);
  EXPECT_FALSE(r.failed());
  EXPECT_EQ(r.u32_le(), 0u) << "three bytes left: past the end reads 0";
  EXPECT_TRUE(r.failed());
}

TEST(ByteReader, AReadPastTheEndFailsAndStaysFailed) {
  const std::vector<std::uint8_t> bytes = {1, 2};
  ByteReader r(bytes);
  EXPECT_EQ(r.u16_le(), 0x0201);
  EXPECT_EQ(r.u8(), 0) << "past the end reads 0";
  EXPECT_TRUE(r.failed());
  EXPECT_TRUE(r.failed()) << "the flag stays set";
  EXPECT_TRUE(ByteReader(bytes).bytes(3).empty());
}

TEST(ByteReader, BytesAreViewsIntoTheInput) {
  const std::vector<std::uint8_t> bytes = {1, 2, 3, 4};
  ByteReader r(bytes);
  r.u8();
  const auto view = r.bytes(2);
  ASSERT_EQ(view.size(), 2u);
  EXPECT_EQ(view.data(), bytes.data() + 1);
  EXPECT_EQ(r.position(), 3u);
}

TEST(ByteReader, RefusesOverlongTooLongAndUnterminatedVarints) {
  auto read = [](std::vector<std::uint8_t> b, std::size_t max_bytes = 5) {
    ByteReader r(b);
    const std::uint32_t v = r.varint(max_bytes);
    return std::pair{v, r.failed()};
  };
  EXPECT_EQ(read({0x80, 0x00}).second, true) << "overlong zero";
  EXPECT_EQ(read({0xFF, 0xFF, 0xFF, 0xFF, 0x1F}).second, true) << "over 32 bits";
  EXPECT_EQ(read({0x80, 0x80}).second, true) << "runs off the end";
  EXPECT_EQ(read({0x80, 0x80, 0x01}, 2).second, true) << "longer than allowed";
  EXPECT_EQ(read({0xFF, 0xFF, 0xFF, 0xFF, 0x0F}), std::pair(0xFFFFFFFFu, false));
}

}  // namespace
}  // namespace fw::codec
