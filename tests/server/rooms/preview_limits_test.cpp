#include "preview_limits.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

PreviewLimits limits(std::size_t max, std::size_t per_address) {
  PreviewLimits l;
  l.max = max;
  l.per_address = per_address;
  l.idle = std::chrono::seconds(600);
  return l;
}

TEST(PreviewCounts, AnAddressHoldsItsShareAndNoMore) {
  PreviewCounts counts(limits(10, 2));
  EXPECT_FALSE(counts.may_open("a"));
  counts.opened("~lab-1", "a");
  counts.opened("~lab-2", "a");
  const auto refusal = counts.may_open("a");
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->code, codec::CloseCode::rate_limited);
  EXPECT_NE(refusal->why.find("2 face-lab previews"), std::string::npos) << refusal->why;
  EXPECT_NE(refusal->why.find("try again in 600 s"), std::string::npos) << refusal->why;
  EXPECT_FALSE(counts.may_open("b")) << "another address has a share of its own";
  counts.closed("~lab-1");
  EXPECT_FALSE(counts.may_open("a")) << "a closed preview gives its place back";
  EXPECT_EQ(counts.held_by("a"), 1u);
}

TEST(PreviewCounts, TheServersLimitHoldsForEveryone) {
  PreviewCounts counts(limits(3, 2));
  counts.opened("~lab-1", "a");
  counts.opened("~lab-2", "b");
  counts.opened("~lab-3", "c");
  const auto refusal = counts.may_open("d");
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->code, codec::CloseCode::server_full);
  EXPECT_NE(refusal->why.find("(3)"), std::string::npos) << refusal->why;
  EXPECT_TRUE(counts.is_preview("~lab-2"));
  counts.closed("~lab-2");
  counts.closed("lobby");  // no preview: nothing changes
  EXPECT_FALSE(counts.may_open("d"));
  EXPECT_EQ(counts.open(), 2u);
}

TEST(PreviewCounts, ZeroTurnsPreviewsOff) {
  PreviewCounts counts(limits(0, 2));
  EXPECT_TRUE(counts.may_open("a"));
}

}  // namespace
}  // namespace fw::server
