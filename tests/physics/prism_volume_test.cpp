#include "fw/physics/prism_volume.hpp"

#include <random>

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

// A right prism: outer triangle at z = 1 (counter-clockwise seen from +z,
// the outside), inner one at z = 0.
PrismNodes unit_prism() {
  return {glm::vec3(0, 0, 1), glm::vec3(1, 0, 1), glm::vec3(0, 1, 1), glm::vec3(0, 0, 0), glm::vec3(1, 0, 0),
          glm::vec3(0, 1, 0)};
}

TEST(PrismVolume, IsAreaTimesHeightForARightPrism) {
  EXPECT_NEAR(prism_volume(unit_prism()), 0.5f, 1e-6f);
}

TEST(PrismVolume, IsNegativeWhenTurnedInsideOut) {
  PrismNodes p = unit_prism();
  for (int k = 0; k < 3; ++k) std::swap(p[static_cast<std::size_t>(k)], p[static_cast<std::size_t>(k + 3)]);
  EXPECT_NEAR(prism_volume(p), -0.5f, 1e-6f);
}

TEST(PrismVolume, GradientMatchesFiniteDifferences) {
  const unsigned seed = 20261122;
  SCOPED_TRACE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.2f, 0.2f);
  PrismNodes p = unit_prism();
  for (glm::vec3& q : p) q += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
  PrismNodes gradient;
  prism_volume(p, &gradient);
  constexpr float h = 1e-3f;
  for (std::size_t k = 0; k < 6; ++k)
    for (int axis = 0; axis < 3; ++axis) {
      PrismNodes plus = p, minus = p;
      plus[k][axis] += h;
      minus[k][axis] -= h;
      EXPECT_NEAR((prism_volume(plus) - prism_volume(minus)) / (2 * h), gradient[k][axis], 2e-3f) << k << " " << axis;
    }
}

// The volume is the solid's, not a numbering's: relabelling the triangles'
// corners (keeping the winding) or mirroring the prism changes nothing but,
// for the mirror, the sign.
TEST(PrismVolume, DoesNotDependOnTheNumberingAndMirrorsExactly) {
  const PrismNodes p = {glm::vec3(0, 0, 1), glm::vec3(1, 0.2f, 1.3f), glm::vec3(0, 1, 0.8f),
                        glm::vec3(0.1f, 0, 0), glm::vec3(0.9f, 0, -0.1f), glm::vec3(0, 0.8f, 0.2f)};
  const PrismNodes rotated = {p[1], p[2], p[0], p[4], p[5], p[3]};
  EXPECT_NEAR(prism_volume(p), prism_volume(rotated), 1e-6f);
  PrismNodes mirrored;
  for (std::size_t k = 0; k < 6; ++k) mirrored[k] = glm::vec3(-p[k].x, p[k].y, p[k].z);
  EXPECT_NEAR(prism_volume(mirrored), -prism_volume(p), 1e-6f);
}

TEST(PrismVolume, TranslationDoesNotChangeIt) {
  PrismNodes p = unit_prism();
  for (glm::vec3& q : p) q += glm::vec3(3, -2, 5);
  PrismNodes gradient;
  EXPECT_NEAR(prism_volume(p, &gradient), 0.5f, 1e-5f);
  glm::vec3 sum(0.0f);
  for (const glm::vec3& g : gradient) sum += g;
  EXPECT_NEAR(glm::length(sum), 0.0f, 1e-5f) << "the gradient of a translation-invariant quantity sums to zero";
}

}  // namespace
}  // namespace fw::physics
