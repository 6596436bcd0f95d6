#include "fw/behavior/emotion_state.hpp"

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(EmotionState, ExpressionsRiseAndEndMoodDecays) {
  EmotionState s;
  s.express(Primary::anger, envelope_for(1, 0.8f, 0.5f));
  for (int i = 0; i < 15; ++i) s.step(1.0 / 30);
  EXPECT_GT(s.point()[2], 0.7f);
  EXPECT_TRUE(s.performing());
  for (int i = 0; i < 90; ++i) s.step(1.0 / 30);
  EXPECT_FALSE(s.performing());
  EXPECT_EQ(s.point()[2], 0);
  s.nudge({0.8f, 0, 0, 0, 0, 0});
  for (int i = 0; i < 120; ++i) s.step(1.0 / 30);
  EXPECT_NEAR(s.point()[0], 0.4f, 0.01f);  // one half-life
}

}  // namespace
}  // namespace fw::behavior
