#include "fw/behavior/facs_track.hpp"

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(FacsTrack, ASentenceBecomesTimedTargets) {
  AuTrack t;
  std::string error;
  ASSERT_TRUE(facs_track("ClearAllFrame BeginKeyFrame 12 1.0 6 0.5 Animate 5 \"Texture\" end", t, error)) << error;
  const int au12 = codec::au_channel(12, codec::AuSide::left);
  EXPECT_EQ(t.at(0)[static_cast<std::size_t>(au12)], 0);
  EXPECT_NEAR(t.at(0.5)[static_cast<std::size_t>(au12)], 1.0f, 1e-5f);  // 5 steps of 0.1 s
  EXPECT_NEAR(t.at(0.25)[static_cast<std::size_t>(au12)], 0.5f, 1e-5f);
  EXPECT_NEAR(t.length_s(), 0.5 + AuTrack::kHoldS + AuTrack::kReleaseS, 1e-9);
  EXPECT_EQ(t.at(t.length_s())[static_cast<std::size_t>(au12)], 0);
}

TEST(FacsTrack, ErrorsSayWhatWasWrong) {
  AuTrack t;
  std::string error;
  EXPECT_FALSE(facs_track("ClearAllFrame BeginKeyFrame 3 1.0 Animate 2 \"Texture\" end", t, error));
  EXPECT_NE(error.find("AU 3"), std::string::npos) << error;
  EXPECT_FALSE(facs_track("[expression x [mpca nose intensity 0.2]]", t, error));
  EXPECT_NE(error.find("no expression sentence"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::behavior
