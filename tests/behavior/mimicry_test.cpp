#include "fw/behavior/mimicry.hpp"

#include <cstdio>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

constexpr double kDt = 1.0 / 30;
constexpr auto kJoy = static_cast<std::size_t>(Primary::joy);
constexpr auto kAnger = static_cast<std::size_t>(Primary::anger);

EmotionPoint only(Primary p, float v) {
  EmotionPoint point{};
  point[static_cast<std::size_t>(p)] = v;
  return point;
}

// A full smile held for 4 s: the mimic starts to smile 0.5-1.5 s later and
// reaches at most 0.6 of it.
TEST(Mimicry, ASmileIsTakenOnLaterAndWeaker) {
  Mimicry m;
  double onset = -1;
  float peak = 0;
  for (int i = 1; i <= 4 * 30; ++i) {
    m.step(kDt, only(Primary::joy, 1.0f));
    peak = std::max(peak, m.point()[kJoy]);
    if (onset < 0 && m.point()[kJoy] > 0.05f) onset = i * kDt;
  }
  std::printf("onset %.2f s, peak %.2f of the leader's\n", onset, peak);
  EXPECT_GE(onset, 0.5);
  EXPECT_LE(onset, 1.5);
  EXPECT_LE(peak, 0.6f);
  EXPECT_GE(peak, 0.4f) << "a smile is returned visibly";
}

TEST(Mimicry, AngerAndDisgustAreNotMimicked) {
  Mimicry m;
  EmotionPoint hostile = only(Primary::anger, 1.0f);
  hostile[static_cast<std::size_t>(Primary::disgust)] = 1.0f;
  for (int i = 0; i < 4 * 30; ++i) m.step(kDt, hostile);
  EXPECT_EQ(m.point()[kAnger], 0.0f);
  EXPECT_EQ(m.point()[static_cast<std::size_t>(Primary::disgust)], 0.0f);
}

TEST(Mimicry, ItFadesOnceTheMimicLooksAway) {
  Mimicry m;
  for (int i = 0; i < 4 * 30; ++i) m.step(kDt, only(Primary::joy, 1.0f));
  const float held = m.point()[kJoy];
  for (int i = 0; i < 30; ++i) m.step(kDt, std::nullopt);
  EXPECT_LT(m.point()[kJoy], 0.25f * held) << "a second after looking away";
  for (int i = 0; i < 60; ++i) m.step(kDt, std::nullopt);
  EXPECT_LT(m.point()[kJoy], 0.02f);
}

// A brief glance at a smile shorter than the latency leaves nothing behind.
TEST(Mimicry, AGlanceShorterThanTheLatencyTakesNothingOn) {
  Mimicry m;
  for (int i = 0; i < 10; ++i) m.step(kDt, only(Primary::joy, 1.0f));
  for (int i = 0; i < 30; ++i) m.step(kDt, std::nullopt);
  EXPECT_EQ(m.point()[kJoy], 0.0f);
}

}  // namespace
}  // namespace fw::behavior
