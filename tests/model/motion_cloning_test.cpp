#include "fw/model/motion_cloning.hpp"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/generic_face.hpp"

namespace fw::model {
namespace {

Morph sample_morph() {
  Morph m;
  const auto& positions = generic_face().skin.positions;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    const float s = static_cast<float>(v % 7) / 7.0f;
    m.vertex_delta.emplace_back(0.01f * s, -0.02f * s, 0.005f);
    m.uv_delta.emplace_back(0.001f * s, 0.002f);
  }
  return m;
}

std::vector<glm::vec2> transformed(const glm::mat2& a) {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic_face().skin.positions) xy.push_back(a * glm::vec2(p));
  return xy;
}

TEST(MotionCloning, IdentityFitLeavesMorphsAlone) {
  const Morph m = sample_morph();
  const Morph cloned = clone_morph(m, fit_jacobians(generic_face().skin, transformed(glm::mat2(1.0f))));
  for (std::size_t v = 0; v < m.vertex_delta.size(); ++v) {
    EXPECT_LT(glm::length(cloned.vertex_delta[v] - m.vertex_delta[v]), 1e-5f);
    EXPECT_LT(glm::length(cloned.uv_delta[v] - m.uv_delta[v]), 1e-6f);
  }
}

TEST(MotionCloning, ScalesWithTheFace) {
  const Morph m = sample_morph();
  const glm::mat2 stretch(1.2f, 0.0f, 0.0f, 0.8f);  // wider and shorter
  const Morph cloned = clone_morph(m, fit_jacobians(generic_face().skin, transformed(stretch)));
  for (std::size_t v = 0; v < m.vertex_delta.size(); ++v) {
    EXPECT_NEAR(cloned.vertex_delta[v].x, 1.2f * m.vertex_delta[v].x, 1e-5f);
    EXPECT_NEAR(cloned.vertex_delta[v].y, 0.8f * m.vertex_delta[v].y, 1e-5f);
    EXPECT_NEAR(cloned.vertex_delta[v].z, std::sqrt(0.96f) * m.vertex_delta[v].z, 1e-5f) << "depth by local scale";
  }
}

TEST(MotionCloning, IsDeterministic) {
  std::vector<glm::vec2> xy = transformed(glm::mat2(1.0f));
  for (std::size_t v = 0; v < xy.size(); ++v) xy[v] += glm::vec2(0.01f * std::sin(static_cast<float>(v)), 0.0f);
  const auto a = clone_morph(sample_morph(), fit_jacobians(generic_face().skin, xy));
  const auto b = clone_morph(sample_morph(), fit_jacobians(generic_face().skin, xy));
  EXPECT_EQ(a.vertex_delta, b.vertex_delta);
}

}  // namespace
}  // namespace fw::model
