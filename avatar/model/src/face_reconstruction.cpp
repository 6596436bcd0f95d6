#include "fw/model/face_reconstruction.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace fw::model {
namespace {

// Upper lid contour points and the lower points they close onto, per eye
// (iBUG order: 37/38 over 41/40, 43/44 over 47/46).
constexpr int kUpper[2][2] = {{37, 38}, {43, 44}};
constexpr int kLower[2][2] = {{41, 40}, {47, 46}};
// Lid skin within this distance of the contour follows it, fading out.
constexpr float kLidReach = 0.12f;

void close_lids(const GenericFace& face, const codec::FaceParams& params, std::vector<glm::vec3>& positions) {
  const float closure[2] = {std::clamp(params.lid_right, 0.0f, 1.0f), std::clamp(params.lid_left, 0.0f, 1.0f)};
  for (std::size_t side = 0; side < 2; ++side) {
    if (closure[side] <= 0.0f) continue;
    glm::vec3 delta[2];
    glm::vec2 at[2];
    for (int k = 0; k < 2; ++k) {
      const glm::vec3 upper = positions[face.landmark_vertices[static_cast<std::size_t>(kUpper[side][k])]];
      const glm::vec3 lower = positions[face.landmark_vertices[static_cast<std::size_t>(kLower[side][k])]];
      // Closed, the upper lid meets the lower one: no slit for the eyeball
      // to show through.
      delta[k] = closure[side] * (lower - upper);
      at[k] = glm::vec2(upper);
    }
    const glm::vec2 eye_centre = glm::vec2(face.eyes[side].centre);
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const glm::vec2 p(positions[v]);
      if (p.y < eye_centre.y - 0.02f) continue;  // only the upper lid moves
      glm::vec3 sum(0.0f);
      float weight = 0.0f;
      for (int k = 0; k < 2; ++k) {
        const float d = glm::length(p - at[k]);
        if (d >= kLidReach) continue;
        const float t = 1.0f - d / kLidReach;
        sum += t * t * delta[k];
        weight += t * t;
      }
      if (weight > 0.0f) positions[v] += sum / std::max(1.0f, weight);
    }
  }
}

}  // namespace

FaceShape reconstruct_face(const AvatarModel& avatar, const codec::FaceParams& params) {
  FaceShape shape;
  shape.positions = avatar.face.skin.positions;
  shape.uvs = avatar.face.skin.uvs;
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const float w = std::clamp(params.au[c], 0.0f, 1.0f);
    if (w == 0.0f) continue;
    const Morph& m = avatar.morphs[c];
    for (std::size_t v = 0; v < shape.positions.size(); ++v) {
      shape.positions[v] += w * m.vertex_delta[v];
      shape.uvs[v] += w * m.uv_delta[v];
    }
  }
  // The physics face's residual components: skin only, no texture slide.
  for (std::size_t k = 0; k < std::min(avatar.correctives.size(), params.corrective.size()); ++k) {
    const float w = std::isfinite(params.corrective[k]) ? std::clamp(params.corrective[k], -1.0f, 1.0f) : 0.0f;
    if (w == 0.0f) continue;
    const std::vector<glm::vec3>& delta = avatar.correctives[k].vertex_delta;
    for (std::size_t v = 0; v < shape.positions.size(); ++v) shape.positions[v] += w * delta[v];
  }
  close_lids(avatar.face, params, shape.positions);
  return shape;
}

}  // namespace fw::model
