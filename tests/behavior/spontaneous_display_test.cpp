#include "fw/behavior/spontaneous_display.hpp"

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

float apex(const Display& d) {
  float most = 0;
  for (double t = 0; t < d.envelope.length_s(); t += 0.01) most = std::max(most, d.envelope.at(t));
  return most;
}

// Nothing felt: only mild social smiles, never a negative primary.
TEST(SpontaneousDisplay, WithNothingFeltOnlyMildSmiles) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Display d = spontaneous_display(EmotionPoint{}, rng);
    ASSERT_EQ(d.primary, Primary::joy);
    EXPECT_LE(apex(d), 0.6f) << "a social smile, not a laugh";
    EXPECT_GE(apex(d), kSocialSmileMin);
  }
}

// A feeling away from neutral is what is shown, at a strength that follows it.
TEST(SpontaneousDisplay, AFeelingIsShownAsFelt) {
  std::mt19937_64 rng(4);
  EmotionPoint sad{};
  sad[static_cast<std::size_t>(Primary::sadness)] = 0.5f;
  for (int i = 0; i < 100; ++i) {
    const Display d = spontaneous_display(sad, rng);
    ASSERT_EQ(d.primary, Primary::sadness);
    EXPECT_GT(apex(d), 0.3f);
    EXPECT_LT(apex(d), 0.9f);
  }
  // Below the neutral radius a feeling is not shown.
  EmotionPoint faint{};
  faint[static_cast<std::size_t>(Primary::anger)] = 0.1f;
  EXPECT_EQ(spontaneous_display(faint, rng).primary, Primary::joy);
}

TEST(SpontaneousDisplay, DisplaysAreSecondsApart) {
  std::mt19937_64 rng(5);
  for (int i = 0; i < 100; ++i) {
    const double after = next_display_after_s(rng);
    EXPECT_GE(after, kDisplayIntervalMinS);
    EXPECT_LE(after, kDisplayIntervalMaxS);
  }
}

}  // namespace
}  // namespace fw::behavior
