// The head shell: closed, joined to the face without a gap, within a head's
// bounds, and fitted to a person's outline.
#include "fw/model/head_shell.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "fw/model/depth_profile.hpp"
#include "fw/model/face_asset.hpp"
#include "fw/model/fitted_face.hpp"

namespace fw::model {
namespace {

std::vector<glm::vec2> rim_of(const GenericFace& face) {
  std::vector<glm::vec2> rim;
  for (std::uint32_t v : face_rim_loop(face.skin)) rim.emplace_back(face.skin.positions[v]);
  return rim;
}

TEST(HeadShell, IsClosedWhereItShowsAndValidationSaysSoWhenItIsNot) {
  GenericFace face = generic_face();
  EXPECT_TRUE(validate_generic_face(face).empty());
  face.head.mesh.triangles.pop_back();
  const auto problems = validate_generic_face(face);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("not closed"), std::string::npos) << problems.front();
}

// Seen from the front, the shell reaches past the face's rim on every ray,
// so no background shows between them; and behind the rim it lies behind
// the face, so the face overlaps it rather than the other way round.
TEST(HeadShell, ReachesPastTheFaceRimAndStaysBehindIt) {
  const GenericFace& face = generic_face();
  const std::vector<glm::vec2> rim = rim_of(face);
  for (std::size_t k = 0; k < face.head.outline.size(); ++k) {
    const float phi = outline_ray_angle(k, face.head.outline.size());
    EXPECT_GT(face.head.outline[k], ray_exit_radius(face.head.centre, phi, rim) + 0.04f) << "ray " << k;
  }
  // Wherever the face is, the shell is behind it: the face's surface runs
  // from the depth profile at its outline to 0.25 behind it at the rim.
  for (std::size_t v = 0; v < face.head.mesh.positions.size(); ++v) {
    const glm::vec3 p = face.head.mesh.positions[v];
    const glm::vec2 xy(p);
    const float phi = std::atan2(xy.y - face.head.centre.y, xy.x - face.head.centre.x);
    if (glm::length(xy - face.head.centre) < ray_exit_radius(face.head.centre, phi, rim)) {
      EXPECT_LT(p.z, face_depth(xy) - 0.25f) << "shell vertex " << v << " pokes through the face";
    }
  }
}

// The shell meets the face along the face's whole rim: on every outline
// ray a vertex of the shell lies on the rim, just behind it. Where the
// shell's rings fell where they might, it stood up to 0.23 in front of the
// rim at the temples (a second outline across a turned face) and up to 0.48
// behind it under the jaw (a jaw that stood off the neck).
TEST(HeadShell, MeetsTheFaceAlongItsRim) {
  const GenericFace& face = generic_face();
  std::vector<glm::vec3> rim;
  for (std::uint32_t v : face_rim_loop(face.skin)) rim.push_back(face.skin.positions[v]);
  for (std::size_t k = 0; k < face.head.outline.size(); ++k) {
    const float phi = outline_ray_angle(k, face.head.outline.size());
    const glm::vec2 direction(std::cos(phi), std::sin(phi));
    const auto [radius, depth] = ray_exit(face.head.centre, phi, rim);
    ASSERT_GT(radius, 0.0f) << "ray " << k;
    const glm::vec2 on_rim = face.head.centre + radius * direction;
    bool met = false;
    for (const glm::vec3& p : face.head.mesh.positions)
      met = met || (glm::length(glm::vec2(p) - on_rim) < 2e-3f && p.z < depth && p.z > depth - 0.05f);
    EXPECT_TRUE(met) << "ray " << k << ": no shell vertex just behind the rim at (" << on_rim.x << ", " << on_rim.y
                     << ", " << depth << ")";
  }
}

TEST(HeadShell, IsTheSizeOfAHeadWithANeck) {
  glm::vec3 low(1e9f), high(-1e9f);
  for (const glm::vec3& p : generic_face().head.mesh.positions) low = glm::min(low, p), high = glm::max(high, p);
  // 63 mm units: about 170 mm across the ears, 220 mm from the nose tip to
  // the back of the head (the shell is open in front, behind the face), the
  // crown 125 mm above the eyes, the neck well below the chin.
  for (const glm::vec3& p : generic_face().skin.positions) high.z = std::max(high.z, p.z);
  EXPECT_NEAR(high.x - low.x, 2.9f, 0.3f);
  EXPECT_NEAR(high.x, -low.x, 1e-4f) << "symmetric";
  EXPECT_NEAR(high.y, 2.0f, 0.2f);
  EXPECT_LT(low.y, -4.0f);
  EXPECT_NEAR(high.z - low.z, 3.5f, 0.3f);
  EXPECT_GT(generic_face().head.mesh.positions.size(), 200u) << "low-polygon, but a head";
  EXPECT_LT(generic_face().head.mesh.positions.size(), 700u);
}

// A person with a larger outline gets a larger shell, still closed, still
// past the rim; the generic outline gives back the generic shell.
TEST(HeadShell, FollowsThePersonsOutline) {
  const GenericFace& generic = generic_face();
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic.skin.positions) xy.emplace_back(p);
  const HeadShell same = fit_head_shell(generic, xy, {});
  for (std::size_t v = 0; v < same.mesh.positions.size(); ++v) {
    EXPECT_NEAR(glm::length(same.mesh.positions[v] - generic.head.mesh.positions[v]), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(same.mesh.uvs[v] - generic.head.mesh.uvs[v]), 0.0f, 1e-4f);
  }
  std::vector<float> wider = generic.head.outline;
  for (float& r : wider) r *= 1.2f;
  const GenericFace fitted = fit_generic_face(generic, xy, wider);
  EXPECT_TRUE(validate_generic_face(fitted).empty());
  for (std::size_t k = 0; k < wider.size(); ++k) EXPECT_NEAR(fitted.head.outline[k], wider[k], 1e-5f);
  float widest = 0.0f, generic_widest = 0.0f;
  for (const glm::vec3& p : fitted.head.mesh.positions) widest = std::max(widest, p.x);
  for (const glm::vec3& p : generic.head.mesh.positions) generic_widest = std::max(generic_widest, p.x);
  EXPECT_NEAR(widest - generic.head.centre.x, 1.2f * (generic_widest - generic.head.centre.x), 0.02f);
}

}  // namespace
}  // namespace fw::model
