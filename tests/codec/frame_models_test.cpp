#include "frame_models.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(FrameModels, ContextsSeparateHistoryActivityAndPartners) {
  FrameModels m;
  std::array<bool, kChannelCount> now{};
  EXPECT_EQ(channel_update_context(m, 0, false, now), 0) << "au1_left: no partner, idle, not updated";
  EXPECT_EQ(channel_update_context(m, 29, false, now), 0) << "head yaw: no partner, idle, not updated";
  EXPECT_EQ(channel_update_context(m, 29, true, now), 2);
  m.updated_last[29] = true;
  EXPECT_EQ(channel_update_context(m, 29, true, now), 3);
  EXPECT_EQ(channel_update_context(m, 1, false, now), 4) << "partner not updated";
  now[0] = true;
  EXPECT_EQ(channel_update_context(m, 1, false, now), 8) << "partner updated";
  m.reset();
  EXPECT_FALSE(m.updated_last[29]);
}

TEST(FrameModels, DampingClassesRoundTrip) {
  RangeEncoder enc;
  std::array<AdaptiveBit, kDampingClasses> e{}, d{};
  const std::vector<int> classes = {0, 1, 2, 3, 4, 5, 6, 7, 7, 7, 0, 3};
  for (int c : classes) encode_damping(enc, e, c);
  std::vector<std::uint8_t> bytes;
  enc.finish(bytes);
  RangeDecoder dec(bytes);
  for (int c : classes) EXPECT_EQ(decode_damping(dec, d), c);
}

}  // namespace
}  // namespace fw::codec
