// Expressions measured on the reconstructed mesh, not read from the code.
#include "fw/model/face_reconstruction.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/expressions.hpp"

namespace fw::model {
namespace {

// A face unlike the template: wider, shorter, a little sheared, so the tests
// also go through motion cloning.
AvatarModel someone() {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic_face().skin.positions) xy.emplace_back(1.08f * p.x + 0.03f * p.y, 0.94f * p.y);
  return make_avatar_model(generic_face(), xy);
}

struct Measured {
  FaceShape neutral, expressive;
  const AvatarModel* avatar;
  glm::vec3 moved(int landmark) const {
    const std::uint32_t v = avatar->face.landmark_vertices[static_cast<std::size_t>(landmark)];
    return expressive.positions[v] - neutral.positions[v];
  }
  float eye_opening(const FaceShape& s, int begin) const {
    const auto at = [&](int i) { return s.positions[avatar->face.landmark_vertices[static_cast<std::size_t>(begin + i)]]; };
    return 0.5f * ((at(1).y - at(5).y) + (at(2).y - at(4).y));
  }
  float opening_change(int begin) const { return eye_opening(expressive, begin) - eye_opening(neutral, begin); }
};

Measured measure(const AvatarModel& avatar, const codec::FaceParams& params) {
  return {reconstruct_face(avatar, {}), reconstruct_face(avatar, params), &avatar};
}

Measured measure_expression(const AvatarModel& avatar, Expression e) {
  codec::FaceParams params;
  apply_expression(e, 1.0f, params);
  return measure(avatar, params);
}

class ReconstructionTest : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override { avatar_ = GetParam() ? someone() : generic_avatar_model(); }
  AvatarModel avatar_;
};

TEST_P(ReconstructionTest, RestIsTheFittedFace) {
  const FaceShape rest = reconstruct_face(avatar_, {});
  EXPECT_EQ(rest.positions, avatar_.face.skin.positions);
  EXPECT_EQ(rest.uvs, avatar_.face.skin.uvs);
}

TEST_P(ReconstructionTest, JoyRaisesTheMouthCornersAndNarrowsTheEyes) {
  const Measured m = measure_expression(avatar_, Expression::joy);
  EXPECT_GT(m.moved(48).y, 0.03f);
  EXPECT_GT(m.moved(54).y, 0.03f);
  EXPECT_LT(m.opening_change(36), -0.005f);
  EXPECT_LT(m.opening_change(42), -0.005f);
}

TEST_P(ReconstructionTest, SurpriseRaisesTheBrowsOpensTheEyesAndTheJaw) {
  const Measured m = measure_expression(avatar_, Expression::surprise);
  for (int brow = 17; brow < 27; ++brow) EXPECT_GT(m.moved(brow).y, 0.02f) << "brow landmark " << brow;
  EXPECT_GT(m.opening_change(36), 0.01f);
  EXPECT_GT(m.opening_change(42), 0.01f);
  EXPECT_LT(m.moved(8).y, -0.1f) << "chin";
  EXPECT_LT(m.moved(57).y, -0.1f) << "lower lip";
}

TEST_P(ReconstructionTest, AngerLowersTheInnerBrows) {
  const Measured m = measure_expression(avatar_, Expression::anger);
  EXPECT_LT(m.moved(21).y, -0.02f);
  EXPECT_LT(m.moved(22).y, -0.02f);
}

TEST_P(ReconstructionTest, SadnessRaisesTheInnerBrowsAndLowersTheMouthCorners) {
  const Measured m = measure_expression(avatar_, Expression::sadness);
  EXPECT_GT(m.moved(21).y, 0.015f);
  EXPECT_GT(m.moved(22).y, 0.015f);
  EXPECT_LT(m.moved(48).y, -0.03f);
  EXPECT_LT(m.moved(54).y, -0.03f);
}

TEST_P(ReconstructionTest, Au12AloneMovesNoBrowVertex) {
  codec::FaceParams params;
  params.set_au(12, 1.0f);
  const Measured m = measure(avatar_, params);
  const GenericFace& face = avatar_.face;
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f) {
    const FaceRegion r = face.triangle_regions[f];
    if (r != FaceRegion::brow_left && r != FaceRegion::brow_right && r != FaceRegion::forehead) continue;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = face.skin.triangles[f][k];
      // The physics-synthesised unit pulls the whole tissue a little: under 1 mm.
      EXPECT_LT(glm::length(m.expressive.positions[v] - m.neutral.positions[v]), 1.0f / kMillimetresPerUnit)
          << "vertex " << v;
      EXPECT_EQ(m.expressive.uvs[v], m.neutral.uvs[v]) << "vertex " << v;
    }
  }
  EXPECT_GT(m.moved(54).y, 0.05f) << "while the lip corner does move";
}

TEST_P(ReconstructionTest, OneSidedUnitMovesOneSide) {
  codec::FaceParams params;
  params.au[static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left))] = 1.0f;
  const Measured m = measure(avatar_, params);
  EXPECT_GT(m.moved(54).y, 0.05f) << "the person's left corner (landmark 54)";
  // The lips pass a little of the pull on to the other corner (physics).
  EXPECT_LT(glm::length(m.moved(48)), 0.2f * glm::length(m.moved(54))) << "the right corner all but stays";
}

TEST_P(ReconstructionTest, ClosedLidsMeet) {
  codec::FaceParams params;
  params.lid_left = params.lid_right = 1.0f;
  const FaceShape closed = reconstruct_face(avatar_, params);
  const auto at = [&](int i) { return closed.positions[avatar_.face.landmark_vertices[static_cast<std::size_t>(i)]]; };
  for (auto [upper, lower] : {std::pair{37, 41}, {38, 40}, {43, 47}, {44, 46}})
    EXPECT_LT(std::abs(at(upper).y - at(lower).y), 0.01f) << upper << " over " << lower;
  params.lid_left = 0.0f;
  const FaceShape one = reconstruct_face(avatar_, params);
  EXPECT_EQ(one.positions[avatar_.face.landmark_vertices[43]], avatar_.face.skin.positions[avatar_.face.landmark_vertices[43]])
      << "the open left eye stays open";
}

TEST_P(ReconstructionTest, IntensitiesAreClamped) {
  codec::FaceParams over, full;
  over.set_au(26, 5.0f);
  full.set_au(26, 1.0f);
  EXPECT_EQ(reconstruct_face(avatar_, over).positions, reconstruct_face(avatar_, full).positions);
}

INSTANTIATE_TEST_SUITE_P(GenericAndFitted, ReconstructionTest, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param_info) { return param_info.param ? std::string("fitted") : std::string("generic"); });

// Mirror images to within what the asset keeps: the AU synthesis writes a
// displacement under 1e-3 model units (0.06 mm) as zero, and a unit's far
// edge may fall either side of that on its two sides (AU 1 at an inner lip
// corner: 0.00099 on one side, 0 on the other). AU 12's corners mirror
// each other to 1e-5.
TEST(Reconstruction, PairedUnitsAreMirrorSymmetricOnTheGenericFace) {
  const AvatarModel avatar = generic_avatar_model();
  codec::FaceParams params;
  params.set_au(12, 1.0f);
  params.set_au(1, 1.0f);
  const FaceShape s = reconstruct_face(avatar, params);
  for (int i = 0; i < kLandmarkCount; ++i) {
    const std::uint32_t v = avatar.face.landmark_vertices[static_cast<std::size_t>(i)];
    const std::uint32_t m = avatar.face.landmark_vertices[static_cast<std::size_t>(mirrored_landmark(i))];
    EXPECT_NEAR(s.positions[v].x, -s.positions[m].x, 1.1e-3f) << i;
    EXPECT_NEAR(s.positions[v].y, s.positions[m].y, 1.1e-3f) << i;
  }
}

}  // namespace
}  // namespace fw::model
