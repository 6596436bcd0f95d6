#include "fw/model/generic_face.hpp"

#include <cmath>
#include <map>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/depth_profile.hpp"
#include "fw/model/face_asset.hpp"

namespace fw::model {
namespace {

namespace lm = landmarks;

glm::vec2 xy(glm::vec3 p) { return {p.x, p.y}; }

TEST(GenericFace, EmbeddedAssetIsSound) {
  const auto problems = validate_generic_face(generic_face());
  for (const auto& p : problems) ADD_FAILURE() << p;
  EXPECT_EQ(generic_face().version, kGenericFaceVersion);
}

TEST(GenericFace, IsLowPolygonButCarriesMorphs) {
  const Mesh& skin = generic_face().skin;
  EXPECT_GE(skin.positions.size(), 150u);
  EXPECT_LE(skin.positions.size(), 800u);
  EXPECT_GE(skin.triangles.size(), 250u);
  EXPECT_LE(skin.triangles.size(), 1500u);
}

TEST(GenericFace, EveryLandmarkIsAnchoredAtItsTemplatePosition) {
  const GenericFace& face = generic_face();
  for (int i = 0; i < kLandmarkCount; ++i) {
    const glm::vec3 p = face.skin.positions[face.landmark_vertices[static_cast<std::size_t>(i)]];
    const glm::vec2 expected = landmark_template()[static_cast<std::size_t>(i)];
    EXPECT_NEAR(p.x, expected.x, 1e-5f) << "landmark " << i;
    EXPECT_NEAR(p.y, expected.y, 1e-5f) << "landmark " << i;
    EXPECT_NEAR(p.z, face_depth(expected), 1e-5f) << "landmark " << i;
  }
}

TEST(GenericFace, UvsAreTheTextureFrameOfThePositions) {
  const GenericFace& face = generic_face();
  for (std::size_t v = 0; v < face.skin.positions.size(); ++v) {
    const glm::vec2 uv = face.texture_frame.to_uv(xy(face.skin.positions[v]));
    EXPECT_NEAR(face.skin.uvs[v].x, uv.x, 1e-5f);
    EXPECT_NEAR(face.skin.uvs[v].y, uv.y, 1e-5f);
  }
}

TEST(GenericFace, PointSetIsMirrorSymmetric) {
  const auto& positions = generic_face().skin.positions;
  for (const glm::vec3& p : positions) {
    bool found = false;
    for (const glm::vec3& q : positions)
      if (glm::length(glm::vec3(-p.x, p.y, p.z) - q) < 1e-4f) found = true;
    EXPECT_TRUE(found) << "no mirror image of (" << p.x << ", " << p.y << ")";
  }
}

TEST(GenericFace, HolesAreExactlyTheEyeContoursAndTheInnerLips) {
  const GenericFace& face = generic_face();
  const auto landmark_set = [&](int begin, int end) {
    std::set<std::uint32_t> s;
    for (int i = begin; i < end; ++i) s.insert(face.landmark_vertices[static_cast<std::size_t>(i)]);
    return s;
  };
  const auto as_set = [](const std::vector<std::uint32_t>& v) { return std::set<std::uint32_t>(v.begin(), v.end()); };
  EXPECT_EQ(as_set(face.eye_holes[0]), landmark_set(lm::kEyeRightBegin, lm::kEyeRightEnd));
  EXPECT_EQ(as_set(face.eye_holes[1]), landmark_set(lm::kEyeLeftBegin, lm::kEyeLeftEnd));
  EXPECT_EQ(as_set(face.mouth_slit), landmark_set(lm::kInnerLipBegin, lm::kInnerLipEnd));
}

// Regions lie where their names say: measured on the triangles' centroids.
TEST(GenericFace, RegionsAreWhereTheirNamesSay) {
  const GenericFace& face = generic_face();
  std::map<FaceRegion, glm::vec2> centroid_sum;
  std::map<FaceRegion, int> count;
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f) {
    const glm::uvec3 t = face.skin.triangles[f];
    const glm::vec2 c = (xy(face.skin.positions[t.x]) + xy(face.skin.positions[t.y]) + xy(face.skin.positions[t.z])) / 3.0f;
    centroid_sum[face.triangle_regions[f]] += c;
    ++count[face.triangle_regions[f]];
  }
  for (std::size_t r = 0; r < kFaceRegionCount; ++r)
    EXPECT_GT(count[static_cast<FaceRegion>(r)], 0) << "region " << kFaceRegionNames[r] << " is empty";
  const auto centre = [&](FaceRegion r) { return centroid_sum[r] / static_cast<float>(std::max(1, count[r])); };
  using R = FaceRegion;
  for (auto [right, left] : {std::pair{R::brow_right, R::brow_left}, {R::upper_lid_right, R::upper_lid_left},
                             {R::lower_lid_right, R::lower_lid_left}, {R::cheek_right, R::cheek_left},
                             {R::mouth_corner_right, R::mouth_corner_left}, {R::jaw_right, R::jaw_left},
                             {R::side_right, R::side_left}}) {
    EXPECT_LT(centre(right).x, 0.0f) << kFaceRegionNames[static_cast<std::size_t>(right)];
    EXPECT_GT(centre(left).x, 0.0f) << kFaceRegionNames[static_cast<std::size_t>(left)];
  }
  EXPECT_GT(centre(R::forehead).y, centre(R::brow_left).y);
  EXPECT_GT(centre(R::brow_left).y, centre(R::upper_lid_left).y);
  EXPECT_GT(centre(R::upper_lid_left).y, centre(R::lower_lid_left).y);
  EXPECT_GT(centre(R::lower_lid_left).y, centre(R::upper_lip).y);
  EXPECT_GT(centre(R::upper_lip).y, centre(R::lower_lip).y);
  EXPECT_GT(centre(R::lower_lip).y, centre(R::chin).y);
  EXPECT_NEAR(centre(R::nose).x, 0.0f, 0.05f);
  EXPECT_GT(centre(R::hairline).y, centre(R::forehead).y);
}

// Seen from the front, a point of the eye hole shows the eyeball if the
// sphere's front point there lies on its cap.
bool cap_covers(const EyeLayer& eye, glm::vec2 p, float yaw, float pitch) {
  const glm::vec2 d = (p - xy(eye.centre)) / eye.radius;
  if (glm::dot(d, d) >= 1.0f) return false;
  const glm::vec3 on_sphere(d, std::sqrt(1.0f - glm::dot(d, d)));
  const glm::vec3 pole(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  return std::acos(glm::clamp(glm::dot(on_sphere, pole), -1.0f, 1.0f)) < eye.cap_angle_rad;
}

TEST(GenericFace, EyeballsFillTheHolesWhenTurnedThirtyDegrees) {
  const GenericFace& face = generic_face();
  const float turn = 30.0f * 3.14159265f / 180.0f;
  for (std::size_t side = 0; side < 2; ++side) {
    const EyeLayer& eye = face.eyes[side];
    for (std::uint32_t v : face.eye_holes[side]) {
      const glm::vec3 contour = face.skin.positions[v];
      EXPECT_LT(eye.centre.z + eye.radius, contour.z) << "the eyeball pokes through the lid";
      // The contour and points halfway to the eye centre, at every extreme gaze.
      for (float t : {1.0f, 0.5f})
        for (auto [yaw, pitch] : {std::pair{turn, 0.0f}, {-turn, 0.0f}, {0.0f, turn}, {0.0f, -turn}, {0.0f, 0.0f}})
          EXPECT_TRUE(cap_covers(eye, glm::mix(xy(eye.centre), xy(contour), t), yaw, pitch))
              << "side " << side << " vertex " << v << " yaw " << yaw << " pitch " << pitch;
    }
  }
}

TEST(GenericFace, MouthCavityIsBehindTheLipsAndCoversTheSlit) {
  const GenericFace& face = generic_face();
  glm::vec2 low(1e9f), high(-1e9f);
  for (const glm::vec3& p : face.mouth_cavity.positions) {
    low = glm::min(low, xy(p));
    high = glm::max(high, xy(p));
    EXPECT_LT(p.z, face_depth(xy(p)) - 0.1f) << "the cavity must sit well behind the skin";
  }
  for (int i = lm::kOuterLipBegin; i < lm::kOuterLipEnd; ++i) {
    const glm::vec3 lip = face.skin.positions[face.landmark_vertices[static_cast<std::size_t>(i)]];
    EXPECT_GT(lip.x, low.x);
    EXPECT_LT(lip.x, high.x);
    EXPECT_GT(lip.y, low.y);
    EXPECT_LT(lip.y, high.y);
  }
}

TEST(GenericFace, RegionNamesRoundTrip) {
  for (std::size_t r = 0; r < kFaceRegionCount; ++r)
    EXPECT_EQ(face_region_from_name(kFaceRegionNames[r]), static_cast<FaceRegion>(r));
  EXPECT_FALSE(face_region_from_name("elbow").has_value());
}

}  // namespace
}  // namespace fw::model
