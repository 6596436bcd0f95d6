#include "fw/model/generic_face.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <set>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/behavior/eye_head.hpp"
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

// The eyeball's mesh turned by `yaw` (toward +x) and `pitch` (up) about its centre.
std::vector<glm::vec3> turned_eyeball(const EyeLayer& eye, float yaw, float pitch) {
  const glm::vec3 pole(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
  const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), pole));
  const glm::vec3 up = glm::cross(pole, right);
  std::vector<glm::vec3> turned;
  for (const glm::vec3& p : eye.mesh.positions) {
    const glm::vec3 d = p - eye.centre;
    turned.push_back(eye.centre + d.x * right + d.y * up + d.z * pole);
  }
  return turned;
}

// Where a line of sight straight into the screen through `p` meets the
// mesh, frontmost first; nothing if it misses.
std::optional<float> front_z_at(const std::vector<glm::vec3>& positions, const Mesh& mesh, glm::vec2 p) {
  std::optional<float> front;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 a = positions[t.x], b = positions[t.y], c = positions[t.z];
    const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (std::abs(area) < 1e-12f) continue;
    const float u = ((b.x - p.x) * (c.y - p.y) - (c.x - p.x) * (b.y - p.y)) / area;
    const float v = ((c.x - p.x) * (a.y - p.y) - (a.x - p.x) * (c.y - p.y)) / area;
    const float w = 1.0f - u - v;
    if (u < 0 || v < 0 || w < 0) continue;
    const float z = u * a.z + v * b.z + w * c.z;
    if (!front || z > *front) front = z;
  }
  return front;
}

TEST(GenericFace, EyeballsAreTheSizeOfARealEye) {
  for (const EyeLayer& eye : generic_face().eyes) {
    EXPECT_GE(eye.radius * kMillimetresPerUnit, 11.0f);
    EXPECT_LE(eye.radius * kMillimetresPerUnit, 13.0f);
    // The front, cornea included, stands no more than 3.5 mm proud of the globe.
    float apex = 0.0f;
    for (const glm::vec3& p : eye.mesh.positions) apex = std::max(apex, p.z - eye.centre.z);
    EXPECT_GE(apex, eye.radius);
    EXPECT_LE(apex * kMillimetresPerUnit, eye.radius * kMillimetresPerUnit + 3.5f);
  }
}

// The lids rest on the eyeball: no part of it in front of the eye contour,
// and its front reaches within 2.5 mm of the contour where the lids cover it
// most (the upper and lower lid's middle).
TEST(GenericFace, EyeballsSitJustBehindTheLids) {
  const GenericFace& face = generic_face();
  for (std::size_t side = 0; side < 2; ++side) {
    const EyeLayer& eye = face.eyes[side];
    const auto& hole = face.eye_holes[side];
    float closest = 1e9f;
    for (std::size_t i = 0; i < hole.size(); ++i)
      for (float t = 0.0f; t < 1.0f; t += 0.125f) {
        const glm::vec3 p = glm::mix(face.skin.positions[hole[i]], face.skin.positions[hole[(i + 1) % hole.size()]], t);
        const auto eyeball = front_z_at(eye.mesh.positions, eye.mesh, xy(p));
        if (!eyeball) continue;
        EXPECT_LT(*eyeball, p.z) << "the eyeball pokes through the lid, side " << side;
        closest = std::min(closest, p.z - *eyeball);
      }
    EXPECT_LT(closest * kMillimetresPerUnit, 2.5f) << "side " << side;
  }
}

// Seen straight from the front, the eye hole shows the eyeball however far
// the behaviour turns the eye (oculomotor range, and the pitch range) up to
// 90 % of the way to its corners; the very tip of the inner corner, when the
// eye turns 46 degrees toward the nose, is left to the renderer's test (the
// portrait camera's perspective covers it, FaceRendererTest).
TEST(GenericFace, EyeballsFillTheHolesAtTheLargestGaze) {
  const GenericFace& face = generic_face();
  const float yaw = behavior::EyeHeadController::kOculomotorRangeRad, pitch = 0.6f;
  for (std::size_t side = 0; side < 2; ++side) {
    const EyeLayer& eye = face.eyes[side];
    for (auto [y, p] : {std::pair{yaw, 0.0f}, {-yaw, 0.0f}, {0.0f, pitch}, {0.0f, -pitch}, {0.0f, 0.0f},
                        {yaw, pitch}, {-yaw, -pitch}}) {
      const auto turned = turned_eyeball(eye, y, p);
      for (std::uint32_t v : face.eye_holes[side])
        for (float t : {0.9f, 0.75f, 0.5f, 0.0f}) {
          const glm::vec2 point = glm::mix(xy(eye.centre), xy(face.skin.positions[v]), t);
          EXPECT_TRUE(front_z_at(turned, eye.mesh, point).has_value())
              << "side " << side << " vertex " << v << " yaw " << y << " pitch " << p;
        }
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
