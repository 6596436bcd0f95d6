#include "fw/physics/muscle_profile.hpp"

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

const glm::vec3 kOrigin(0, 0, 0), kInsertion(1, 0, 0);

TEST(LinearMuscleWeight, PeaksAtTheInsertionOnTheAxis) {
  EXPECT_NEAR(linear_muscle_weight(kInsertion, kOrigin, kInsertion, 0.2f, 0.3f, 0.3f), 1.0f, 1e-6f);
}

TEST(LinearMuscleWeight, GrowsAlongTheMuscleAndFadesBeyondIt) {
  auto w = [](float x) { return linear_muscle_weight({x, 0, 0}, kOrigin, kInsertion, 0.2f, 0.3f, 0.3f); };
  EXPECT_EQ(w(0.2f), 0.0f) << "no pull near the origin";
  EXPECT_LT(w(0.5f), w(0.8f));
  EXPECT_GT(w(1.1f), w(1.2f));
  EXPECT_EQ(w(1.31f), 0.0f) << "nothing past the reach";
}

TEST(LinearMuscleWeight, FadesSidewaysToZeroAtTheWidth) {
  auto w = [](float y) { return linear_muscle_weight({1, y, 0}, kOrigin, kInsertion, 0.2f, 0.3f, 0.3f); };
  EXPECT_GT(w(0.05f), w(0.15f));
  EXPECT_NEAR(w(0.05f), w(-0.05f), 1e-6f);
  EXPECT_EQ(w(0.2f), 0.0f);
}

TEST(SphincterWeight, IsOneOnTheEllipseAndZeroAtTheCentreAndFarAway) {
  const glm::vec3 centre(0, 0, 0);
  EXPECT_NEAR(sphincter_weight({0.4f, 0, 0}, centre, 0.4f, 0.2f, 0.5f), 1.0f, 1e-6f);
  EXPECT_NEAR(sphincter_weight({0, 0.2f, 0}, centre, 0.4f, 0.2f, 0.5f), 1.0f, 1e-6f);
  EXPECT_EQ(sphincter_weight(centre, centre, 0.4f, 0.2f, 0.5f), 0.0f);
  EXPECT_EQ(sphincter_weight({1, 0, 0}, centre, 0.4f, 0.2f, 0.5f), 0.0f);
}

}  // namespace
}  // namespace fw::physics
