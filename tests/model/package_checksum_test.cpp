// The package CRC-32 is zlib's (avatar/photo/FORMAT.md), now written out in
// avatar/model: the standard check values of CRC-32/ISO-HDLC prove it is.
#include "package_checksum.hpp"

#include <string_view>

#include <gtest/gtest.h>

namespace fw::model {
namespace {

std::uint32_t crc_of_text(std::string_view text) {
  return crc_of({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

TEST(PackageChecksum, MatchesTheStandardCheckValues) {
  EXPECT_EQ(crc_of_text(""), 0x00000000u);
  EXPECT_EQ(crc_of_text("123456789"), 0xCBF43926u);
  EXPECT_EQ(crc_of_text("The quick brown fox jumps over the lazy dog"), 0x414FA339u);
}

TEST(PackageChecksum, ChangesWithEveryByte) {
  EXPECT_NE(crc_of_text("facewire"), crc_of_text("facewirf"));
  EXPECT_NE(crc_of_text("facewire"), crc_of_text("facewire "));
}

}  // namespace
}  // namespace fw::model
