#include "build_action_units.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <glm/geometric.hpp>

#include "action_unit_definitions.hpp"

namespace fw::facegen {
namespace {

using model::FaceRegion;

FaceRegion mirrored(FaceRegion r) {
  switch (r) {
    case FaceRegion::brow_left: return FaceRegion::brow_right;
    case FaceRegion::brow_right: return FaceRegion::brow_left;
    case FaceRegion::upper_lid_left: return FaceRegion::upper_lid_right;
    case FaceRegion::upper_lid_right: return FaceRegion::upper_lid_left;
    case FaceRegion::lower_lid_left: return FaceRegion::lower_lid_right;
    case FaceRegion::lower_lid_right: return FaceRegion::lower_lid_left;
    case FaceRegion::cheek_left: return FaceRegion::cheek_right;
    case FaceRegion::cheek_right: return FaceRegion::cheek_left;
    case FaceRegion::mouth_corner_left: return FaceRegion::mouth_corner_right;
    case FaceRegion::mouth_corner_right: return FaceRegion::mouth_corner_left;
    case FaceRegion::jaw_left: return FaceRegion::jaw_right;
    case FaceRegion::jaw_right: return FaceRegion::jaw_left;
    case FaceRegion::side_left: return FaceRegion::side_right;
    case FaceRegion::side_right: return FaceRegion::side_left;
    default: return r;
  }
}

// The right-side unit is the left one seen in a mirror.
ActionUnitDefinition mirrored(ActionUnitDefinition d) {
  for (Handle& h : d.handles) {
    if (h.landmark >= 0) h.landmark = model::mirrored_landmark(h.landmark);
    h.point.x = -h.point.x;
    h.displacement.x = -h.displacement.x;
  }
  for (FaceRegion& r : d.regions) r = mirrored(r);
  return d;
}

float falloff(float distance, float radius) {
  if (distance >= radius) return 0.0f;
  const float t = distance / radius;
  return (1.0f - t * t) * (1.0f - t * t);
}

// How much of the jaw's turn a vertex follows: the lower lip all of it, the
// upper lip none, corners half, other skin by height.
float jaw_share(const std::set<FaceRegion>& regions, float y, const JawRotation& jaw) {
  const bool lower = regions.contains(FaceRegion::lower_lip), upper = regions.contains(FaceRegion::upper_lip);
  if (lower && upper) return 0.5f;
  if (lower) return 1.0f;
  if (upper) return 0.0f;
  const float t = std::clamp((jaw.none_above_y - y) / (jaw.none_above_y - jaw.full_below_y), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec3 jaw_displacement(glm::vec3 p, const JawRotation& jaw) {
  const float c = std::cos(jaw.angle_rad), s = std::sin(jaw.angle_rad);
  const glm::vec2 q(p.y - jaw.hinge.y, p.z - jaw.hinge.z);
  return {0.0f, c * q.x - s * q.y - q.x, s * q.x + c * q.y - q.y};
}

}  // namespace

std::array<model::Morph, codec::kAuChannelCount> build_action_units(const model::GenericFace& face) {
  const std::size_t n = face.skin.positions.size();
  std::vector<std::set<FaceRegion>> vertex_regions(n);
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) vertex_regions[face.skin.triangles[f][k]].insert(face.triangle_regions[f]);

  std::array<model::Morph, codec::kAuChannelCount> units;
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const codec::AuChannel channel = codec::kAuChannels[c];
    ActionUnitDefinition d = action_unit_definition(channel.au);
    if (channel.side == codec::AuSide::right) d = mirrored(d);
    const std::set<FaceRegion> allowed(d.regions.begin(), d.regions.end());

    model::Morph& morph = units[c];
    morph.vertex_delta.assign(n, glm::vec3(0.0f));
    morph.uv_delta.assign(n, glm::vec2(0.0f));
    for (std::size_t v = 0; v < n; ++v) {
      const auto& regions = vertex_regions[v];
      if (!std::any_of(regions.begin(), regions.end(), [&](FaceRegion r) { return allowed.contains(r); })) continue;
      const glm::vec3 p = face.skin.positions[v];
      glm::vec3 sum(0.0f);
      float weight = 0.0f;
      for (const Handle& h : d.handles) {
        const glm::vec2 at = h.landmark >= 0 ? model::landmark_template()[static_cast<std::size_t>(h.landmark)] : h.point;
        const float w = falloff(glm::length(glm::vec2(p) - at), h.radius);
        sum += w * h.displacement;
        weight += w;
      }
      glm::vec3 field = sum / std::max(1.0f, weight);
      if (d.jaw) field += jaw_share(regions, p.y, *d.jaw) * jaw_displacement(p, *d.jaw);
      morph.vertex_delta[v] = d.mesh_share * field;
      // The rest of the motion slides the picture: apparent = dV - dUV * size.
      morph.uv_delta[v] = -(1.0f - d.mesh_share) * glm::vec2(field) / face.texture_frame.size;
    }
  }
  return units;
}

}  // namespace fw::facegen
