#include "thin_plate_spline.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace fw::photo {
namespace {

const std::vector<glm::vec2> kPoints = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5f, 0.4f}, {0.2f, 0.8f}};

TEST(ThinPlateSpline, ReproducesAnAffineMapEverywhere) {
  std::vector<glm::vec2> moved;
  const auto affine = [](glm::vec2 p) { return glm::vec2(2 * p.x - 0.5f * p.y + 3, 0.3f * p.x + 1.5f * p.y - 1); };
  for (const glm::vec2& p : kPoints) moved.push_back(affine(p));
  ThinPlateSpline tps;
  ASSERT_TRUE(tps.fit(kPoints, moved, 0.0f));
  for (const glm::vec2 p : {glm::vec2(0.3f, 0.7f), glm::vec2(-2, 5), glm::vec2(10, -3)})
    EXPECT_LT(glm::length(tps(p) - affine(p)), 1e-3f) << "no bending energy is needed for an affine map";
}

TEST(ThinPlateSpline, InterpolatesItsPointsExactlyWithoutRegularization) {
  std::vector<glm::vec2> moved = kPoints;
  moved[4] += glm::vec2(0.1f, -0.2f);
  ThinPlateSpline tps;
  ASSERT_TRUE(tps.fit(kPoints, moved, 0.0f));
  for (std::size_t i = 0; i < kPoints.size(); ++i) EXPECT_LT(glm::length(tps(kPoints[i]) - moved[i]), 1e-4f);
  // Regularization trades exactness for smoothness.
  ASSERT_TRUE(tps.fit(kPoints, moved, 1.0f));
  EXPECT_GT(glm::length(tps(kPoints[4]) - moved[4]), 1e-3f);
}

TEST(ThinPlateSpline, RefusesTooFewPoints) {
  ThinPlateSpline tps;
  EXPECT_FALSE(tps.fit(std::vector<glm::vec2>{{0, 0}, {1, 1}}, std::vector<glm::vec2>{{0, 0}, {1, 1}}, 0.0f));
}

}  // namespace
}  // namespace fw::photo
