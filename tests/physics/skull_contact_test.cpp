#include "fw/physics/skull_contact.hpp"

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

TEST(ResolveSkullContact, PushesANodeBackOutAndKeepsItsSlide) {
  glm::vec3 p(0.3f, -0.1f, 0.2f), v(1.0f, 0.0f, -2.0f);
  ASSERT_TRUE(resolve_skull_contact({0, 0, 0}, {0, 0, 1}, 0.5f, p, v));
  EXPECT_FLOAT_EQ(p.z, 0.5f);
  EXPECT_FLOAT_EQ(p.x, 0.3f) << "tangential position kept";
  EXPECT_FLOAT_EQ(v.z, 0.0f) << "no speed into the bone";
  EXPECT_FLOAT_EQ(v.x, 1.0f) << "the tissue slides";
}

TEST(ResolveSkullContact, LeavesANodeAboveTheSkullAlone) {
  glm::vec3 p(0, 0, 1), v(0, 0, -3);
  EXPECT_FALSE(resolve_skull_contact({0, 0, 0}, {0, 0, 1}, 0.5f, p, v));
  EXPECT_EQ(p, glm::vec3(0, 0, 1));
  EXPECT_EQ(v, glm::vec3(0, 0, -3));
}

TEST(ResolveSkullContact, KeepsAnOutwardSpeed) {
  glm::vec3 p(0, 0, 0), v(0, 0, 2);
  ASSERT_TRUE(resolve_skull_contact({0, 0, 0}, {0, 0, 1}, 0.1f, p, v));
  EXPECT_FLOAT_EQ(v.z, 2.0f);
}

}  // namespace
}  // namespace fw::physics
