#include "fw/physics/distance_constraint.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace fw::physics {
namespace {

TEST(SolveDistance, RestoresTheRestLengthWithFullStiffness) {
  const glm::vec3 p0(0, 0, 0), p1(2, 0, 0);
  glm::vec3 c0, c1;
  ASSERT_TRUE(solve_distance(p0, 1.0f, p1, 1.0f, 1.0f, 1.0f, c0, c1));
  EXPECT_NEAR(glm::length((p0 + c0) - (p1 + c1)), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(c0), glm::length(c1), 1e-6f) << "equal masses move equally";
}

TEST(SolveDistance, ConservesMomentumWithUnequalMasses) {
  const glm::vec3 p0(0, 0, 0), p1(0, 3, 0);
  glm::vec3 c0, c1;
  ASSERT_TRUE(solve_distance(p0, 1.0f, p1, 3.0f, 1.0f, 1.0f, c0, c1));
  // Masses are 1/w: m0*c0 + m1*c1 = 0.
  EXPECT_NEAR(glm::length(1.0f * c0 + (1.0f / 3.0f) * c1), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length((p0 + c0) - (p1 + c1)), 1.0f, 1e-6f);
}

TEST(SolveDistance, FixedParticleDoesNotMove) {
  glm::vec3 c0, c1;
  ASSERT_TRUE(solve_distance({0, 0, 0}, 0.0f, {0, 0, 2}, 1.0f, 1.0f, 1.0f, c0, c1));
  EXPECT_EQ(c0, glm::vec3(0.0f));
  EXPECT_NEAR(c1.z, -1.0f, 1e-6f);
}

TEST(SolveDistance, StiffnessScalesTheCorrection) {
  glm::vec3 c0, c1;
  ASSERT_TRUE(solve_distance({0, 0, 0}, 0.0f, {0, 0, 2}, 1.0f, 1.0f, 0.25f, c0, c1));
  EXPECT_NEAR(c1.z, -0.25f, 1e-6f);
}

TEST(SolveDistance, RefusesWhatItCannotSolve) {
  glm::vec3 c0(1.0f), c1(1.0f);
  EXPECT_FALSE(solve_distance({0, 0, 0}, 0.0f, {1, 0, 0}, 0.0f, 0.5f, 1.0f, c0, c1)) << "both fixed";
  EXPECT_EQ(c0, glm::vec3(0.0f));
  EXPECT_FALSE(solve_distance({1, 1, 1}, 1.0f, {1, 1, 1}, 1.0f, 0.5f, 1.0f, c0, c1)) << "coincident: no direction";
}

}  // namespace
}  // namespace fw::physics
