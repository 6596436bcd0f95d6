#include "assign_regions.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "fw/model/landmark_template.hpp"

namespace fw::facegen {
namespace {

using model::FaceRegion;
namespace lm = model::landmarks;

FaceRegion sided(float x, FaceRegion right, FaceRegion left) { return x < 0 ? right : left; }

glm::vec2 landmark(int i) { return model::landmark_template()[static_cast<std::size_t>(i)]; }

// The brow as a band: the brow landmarks and the same line raised by the
// row of vertices placed above it.
std::vector<glm::vec2> brow_band(int begin, int end) {
  std::vector<glm::vec2> band;
  for (int i = begin; i < end; ++i) band.push_back(landmark(i) - glm::vec2(0.0f, 0.03f));
  for (int i = end - 1; i >= begin; --i) band.push_back(landmark(i) + glm::vec2(0.0f, 0.14f));
  return band;
}

// The nose from the bridge between the eyes to the nostrils and wings.
std::vector<glm::vec2> nose_outline() {
  return {{-0.11f, 0.1f},  {-0.16f, -0.3f},  {-0.34f, -0.6f}, landmark(31) + glm::vec2(-0.04f, -0.03f),
          landmark(32), landmark(33), landmark(34), landmark(35) + glm::vec2(0.04f, -0.03f),
          {0.34f, -0.6f}, {0.16f, -0.3f}, {0.11f, 0.1f}};
}

}  // namespace

FaceRegion region_of(glm::vec2 c, const FacePoints& face) {
  if (!inside_polygon(c, polygon_of(face, face.outline)))
    return c.y > 0.25f ? FaceRegion::hairline : sided(c.x, FaceRegion::side_right, FaceRegion::side_left);

  if (inside_polygon(c, landmark_polygon(lm::kOuterLipBegin, lm::kOuterLipEnd)))
    return c.y > landmark(62).y - 0.007f ? FaceRegion::upper_lip : FaceRegion::lower_lip;
  if (glm::length(c - landmark(lm::kMouthCornerRight)) < 0.17f) return FaceRegion::mouth_corner_right;
  if (glm::length(c - landmark(lm::kMouthCornerLeft)) < 0.17f) return FaceRegion::mouth_corner_left;

  if (inside_polygon(c, brow_band(lm::kBrowRightBegin, lm::kBrowRightEnd))) return FaceRegion::brow_right;
  if (inside_polygon(c, brow_band(lm::kBrowLeftBegin, lm::kBrowLeftEnd))) return FaceRegion::brow_left;

  // Lids: around each eye, up to the brow above and a lid's height below.
  for (const float eye_x : {-0.5f, 0.5f}) {
    const float dx = std::abs(c.x - eye_x);
    if (dx > 0.36f) continue;
    if (c.y >= -0.01f && c.y < 0.36f) return sided(c.x, FaceRegion::upper_lid_right, FaceRegion::upper_lid_left);
    if (c.y < -0.01f && c.y > -0.24f) return sided(c.x, FaceRegion::lower_lid_right, FaceRegion::lower_lid_left);
  }

  if (inside_polygon(c, nose_outline())) return FaceRegion::nose;
  if (c.y > 0.3f || (std::abs(c.x) < 0.2f && c.y > 0.0f)) return FaceRegion::forehead;
  if (c.y < -1.3f && std::abs(c.x) < 0.5f) return FaceRegion::chin;
  if (c.y < -1.0f) return sided(c.x, FaceRegion::jaw_right, FaceRegion::jaw_left);
  return sided(c.x, FaceRegion::cheek_right, FaceRegion::cheek_left);
}

}  // namespace fw::facegen
