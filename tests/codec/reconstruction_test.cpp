#include "reconstruction.hpp"

#include <gtest/gtest.h>

namespace fw::codec {
namespace {

TEST(Reconstruction, HoldsAValueAndExtrapolatesAVelocityUpToTheLimit) {
  Reconstruction r(10);
  r.set(0, 100, 2 * kSubSteps);  // 2 steps per tick
  EXPECT_EQ(r.shown(0), 100);
  r.advance(3);
  EXPECT_EQ(r.shown(0), 106);
  EXPECT_EQ(r.shown_after(0, 4), 114);
  EXPECT_EQ(r.shown_after(0, 100), 120) << "at most 10 ticks of motion";
  r.advance(1000);
  EXPECT_EQ(r.shown(0), 120);
  EXPECT_EQ(r.age(0), 10u) << "ages stop at the limit";
}

TEST(Reconstruction, ClampsToTheCodedRangeAndRoundsToNearest) {
  Reconstruction r(32);
  r.set(0, 250, 3 * kSubSteps);
  r.advance(10);
  EXPECT_EQ(r.shown(0), 256);
  r.set(1, 0, -kSubSteps);
  r.advance(5);
  EXPECT_EQ(r.shown(1), 0);
  r.set(2, 10, kSubSteps / 2);  // half a step per tick: 10.5 rounds up
  r.advance(1);
  EXPECT_EQ(r.shown(2), 11);
  r.set(29, -10, -kSubSteps / 2);
  r.advance(1);
  EXPECT_EQ(r.shown(29), -10) << "-10.5 rounds up too";
}

TEST(Reconstruction, DampedVelocitiesGlideToARest) {
  Reconstruction r(255);
  r.set(29, 0, 40 * kSubSteps, 7);  // a quarter of the velocity goes every tick
  r.advance(1);
  EXPECT_EQ(r.shown(29), 40);
  r.advance(1);
  EXPECT_EQ(r.shown(29), 70);
  r.advance(200);
  EXPECT_NEAR(r.shown(29), 160, 1) << "40 / (1 - 0.75)";
  EXPECT_EQ(r.damping(29), 7);
}

TEST(Reconstruction, FreezeStopsEveryChannelWhereItIsShown) {
  Reconstruction r(32);
  r.set(0, 10, kSubSteps);
  r.advance(5);
  r.freeze();
  EXPECT_EQ(r.shown(0), 15);
  r.advance(5);
  EXPECT_EQ(r.shown(0), 15);
  EXPECT_EQ(r.velocity(0), 0);
  r.reset();
  EXPECT_EQ(r.shown(0), 0);
}

TEST(Reconstruction, ZeroLimitMeansHold) {
  Reconstruction r(0);
  r.set(0, 10, 5 * kSubSteps);
  r.advance(3);
  EXPECT_EQ(r.shown(0), 10);
}

}  // namespace
}  // namespace fw::codec
