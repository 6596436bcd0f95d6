#include "fw/model/fitted_face.hpp"

#include <gtest/gtest.h>

#include "fw/model/face_asset.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::model {
namespace {

std::vector<glm::vec2> generic_xy() {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic_face().skin.positions) xy.emplace_back(p.x, p.y);
  return xy;
}

TEST(FittedFace, IdentityFitIsTheGenericFace) {
  const GenericFace fitted = fit_generic_face(generic_face(), generic_xy());
  EXPECT_EQ(fitted.skin.triangles, generic_face().skin.triangles);
  for (std::size_t v = 0; v < fitted.skin.positions.size(); ++v) {
    EXPECT_EQ(fitted.skin.positions[v], generic_face().skin.positions[v]);
    EXPECT_NEAR(fitted.skin.uvs[v].x, generic_face().skin.uvs[v].x, 1e-5f);
    EXPECT_NEAR(fitted.skin.uvs[v].y, generic_face().skin.uvs[v].y, 1e-5f);
  }
  EXPECT_EQ(fitted.eyes[0].centre, generic_face().eyes[0].centre);
}

TEST(FittedFace, KeepsDepthMovesUvsAndLayers) {
  std::vector<glm::vec2> xy = generic_xy();
  for (glm::vec2& p : xy) p = p * 1.05f + glm::vec2(0.02f, -0.03f);  // a slightly larger face, a little shifted
  const GenericFace fitted = fit_generic_face(generic_face(), xy);
  const auto problems = validate_generic_face(fitted);
  EXPECT_TRUE(problems.empty()) << problems.front();
  for (std::size_t v = 0; v < xy.size(); ++v) {
    EXPECT_EQ(fitted.skin.positions[v].z, generic_face().skin.positions[v].z) << "template depth kept";
    EXPECT_EQ(fitted.skin.uvs[v], fitted.texture_frame.to_uv(xy[v])) << "the texture is aligned to the model frame";
  }
  // The left eyeball follows the left eye contour's shift.
  const glm::vec3 moved = fitted.eyes[1].centre - generic_face().eyes[1].centre;
  EXPECT_NEAR(moved.x, 0.02f + 0.05f * generic_face().eyes[1].centre.x, 0.01f);
  EXPECT_FLOAT_EQ(moved.z, 0.0f);
}

}  // namespace
}  // namespace fw::model
