#include "package_assembler.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

using Quality = codec::PackageChunk::Quality;

codec::PackageChunk chunk(std::uint32_t avatar, Quality quality, std::uint32_t total, std::uint32_t offset,
                          std::vector<std::uint8_t> data) {
  return {avatar, quality, total, offset, std::move(data)};
}

TEST(PackageAssembler, JoinsInOrderChunksOfInterleavedPackages) {
  PackageAssembler assembler;
  std::string error;
  EXPECT_FALSE(assembler.add(chunk(1, Quality::full, 5, 0, {1, 2}), error));
  EXPECT_FALSE(assembler.add(chunk(2, Quality::preview, 2, 0, {9}), error));
  const auto second = assembler.add(chunk(2, Quality::preview, 2, 1, {8}), error);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->bytes, (std::vector<std::uint8_t>{9, 8}));
  const auto first = assembler.add(chunk(1, Quality::full, 5, 2, {3, 4, 5}), error);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->avatar, 1u);
  EXPECT_EQ(first->quality, Quality::full);
  EXPECT_EQ(first->bytes, (std::vector<std::uint8_t>{1, 2, 3, 4, 5}));
  EXPECT_TRUE(error.empty()) << error;
}

TEST(PackageAssembler, DropsAPackageWithAGapOrAnOverrun) {
  PackageAssembler assembler;
  std::string error;
  assembler.add(chunk(1, Quality::full, 4, 0, {1}), error);
  EXPECT_FALSE(assembler.add(chunk(1, Quality::full, 4, 2, {3, 4}), error));
  EXPECT_NE(error.find("out of order"), std::string::npos);
  error.clear();
  EXPECT_FALSE(assembler.add(chunk(1, Quality::full, 4, 3, {4}), error)) << "the package restarts at offset 0 only";
  assembler.add(chunk(1, Quality::full, 2, 0, {1}), error);
  EXPECT_FALSE(assembler.add(chunk(1, Quality::full, 2, 1, {2, 3}), error));
  EXPECT_FALSE(error.empty());
}

TEST(PackageAssembler, RefusesOversizedAnnouncementsBeforeBuffering) {
  PackageAssembler assembler;
  std::string error;
  EXPECT_FALSE(assembler.add(chunk(1, Quality::full, kMaxAssembledBytes + 1, 0, {1}), error));
  EXPECT_NE(error.find("announced"), std::string::npos);
}

TEST(PackageAssembler, ForgetsADepartedAvatar) {
  PackageAssembler assembler;
  std::string error;
  assembler.add(chunk(4, Quality::full, 2, 0, {1}), error);
  assembler.forget(4);
  EXPECT_FALSE(assembler.add(chunk(4, Quality::full, 2, 1, {2}), error));
}

}  // namespace
}  // namespace fw::client
