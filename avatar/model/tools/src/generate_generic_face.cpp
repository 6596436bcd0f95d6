#include "fw/facegen/generate_generic_face.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "assign_regions.hpp"
#include "build_action_units.hpp"
#include "eyeball.hpp"
#include "face_points.hpp"
#include "head_shell.hpp"
#include "fw/model/depth_profile.hpp"
#include "triangulate.hpp"

namespace fw::facegen {
namespace {

using model::GenericFace;
using model::Mesh;
namespace lm = model::landmarks;

// The texture square: the whole head seen from the front, hair with some
// volume over the crown, the ears, and the neck down to the collar, with room
// for heads larger than the template once fitted.
constexpr model::TextureFrame kTextureFrame{{-2.7f, -3.0f}, 5.4f};
// How far the rim is pulled back beyond the depth profile: it is the turn of
// the head toward the ears and the crown, seen only when the head turns.
constexpr float kRimSetBack = 0.25f;

void add_loop(const std::vector<std::uint32_t>& loop, std::vector<std::pair<unsigned, unsigned>>& edges) {
  for (std::size_t i = 0; i < loop.size(); ++i) edges.emplace_back(loop[i], loop[(i + 1) % loop.size()]);
}

std::vector<std::uint32_t> landmark_loop(int begin, int end) {
  std::vector<std::uint32_t> loop;
  for (int i = begin; i < end; ++i) loop.push_back(static_cast<std::uint32_t>(i));
  return loop;
}

// Skin triangles inside the outer boundary but outside the eyes and the
// mouth slit. Constraints make every triangle lie wholly on one side of each
// boundary, so its centroid decides.
bool is_skin(glm::vec2 centroid, const FacePoints& face) {
  return inside_polygon(centroid, polygon_of(face, face.rim)) &&
         !inside_polygon(centroid, landmark_polygon(lm::kEyeRightBegin, lm::kEyeRightEnd)) &&
         !inside_polygon(centroid, landmark_polygon(lm::kEyeLeftBegin, lm::kEyeLeftEnd)) &&
         !inside_polygon(centroid, landmark_polygon(lm::kInnerLipBegin, lm::kInnerLipEnd));
}

void build_skin(GenericFace& face) {
  const FacePoints points = place_face_points();
  std::vector<std::pair<unsigned, unsigned>> constraints;
  add_loop(points.rim, constraints);
  add_loop(points.outline, constraints);
  add_loop(landmark_loop(lm::kEyeRightBegin, lm::kEyeRightEnd), constraints);
  add_loop(landmark_loop(lm::kEyeLeftBegin, lm::kEyeLeftEnd), constraints);
  add_loop(landmark_loop(lm::kOuterLipBegin, lm::kOuterLipEnd), constraints);
  add_loop(landmark_loop(lm::kInnerLipBegin, lm::kInnerLipEnd), constraints);

  Mesh& skin = face.skin;
  for (std::size_t i = 0; i < points.points.size(); ++i) {
    const glm::vec2 p = points.points[i];
    const float set_back = i >= points.first_rim_point ? kRimSetBack : 0.0f;
    skin.positions.emplace_back(p, model::face_depth(p) - set_back);
    skin.uvs.push_back(kTextureFrame.to_uv(p));
  }
  for (const glm::uvec3& t : constrained_delaunay(points.points, constraints)) {
    const glm::vec2 centroid = (points.points[t.x] + points.points[t.y] + points.points[t.z]) / 3.0f;
    if (!is_skin(centroid, points)) continue;
    skin.triangles.push_back(t);
    face.triangle_regions.push_back(region_of(centroid, points));
  }
  for (int i = 0; i < model::kLandmarkCount; ++i)
    face.landmark_vertices[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(i);

  // The holes are the boundary loops through landmarks 36, 42 and 60.
  for (auto& loop : model::boundary_loops(skin)) {
    const auto has = [&](std::uint32_t v) { return std::find(loop.begin(), loop.end(), v) != loop.end(); };
    if (has(lm::kEyeRightBegin)) face.eye_holes[0] = loop;
    else if (has(lm::kEyeLeftBegin)) face.eye_holes[1] = loop;
    else if (has(lm::kInnerLipBegin)) face.mouth_slit = loop;
  }
}

// A dark, curved backdrop behind the lips: what shows when the mouth opens.
void build_mouth_cavity(GenericFace& face) {
  constexpr int kColumns = 9, kRows = 7;
  // Deep enough below the lips for the widest jaw drop (AU 27).
  constexpr float kHalfWidth = 0.56f, kTop = -0.9f, kBottom = -1.85f;
  Mesh& mesh = face.mouth_cavity;
  for (int row = 0; row < kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      const float u = static_cast<float>(column) / (kColumns - 1);
      const float v = static_cast<float>(row) / (kRows - 1);
      const glm::vec2 p(-kHalfWidth + 2 * kHalfWidth * u, kBottom + (kTop - kBottom) * v);
      const float across = p.x / kHalfWidth;
      // Below the lips the cavity recedes fast: the jaw, turning open, carries
      // the chin's skin back, and the cavity must stay behind it.
      const float depth = model::face_depth(p) - 0.14f - 0.12f * (1.0f - across * across) -
                          0.9f * std::max(0.0f, -1.15f - p.y);
      mesh.positions.emplace_back(p, depth);
      mesh.uvs.emplace_back(u, v);
    }
  const auto at = [](int row, int column) { return static_cast<std::uint32_t>(row * kColumns + column); };
  for (int row = 0; row + 1 < kRows; ++row)
    for (int column = 0; column + 1 < kColumns; ++column) {
      mesh.triangles.emplace_back(at(row, column), at(row, column + 1), at(row + 1, column + 1));
      mesh.triangles.emplace_back(at(row, column), at(row + 1, column + 1), at(row + 1, column));
    }
}

}  // namespace

GenericFace generate_generic_face() {
  GenericFace face;
  face.texture_frame = kTextureFrame;
  build_skin(face);
  build_eyes(face);
  build_mouth_cavity(face);
  face.head = build_head_shell(face.skin, kTextureFrame);
  face.action_units = build_action_units(face);
  return face;
}

}  // namespace fw::facegen
