#include "fw/behavior/au_definition_morph.hpp"

#include <algorithm>
#include <set>

#include <glm/geometric.hpp>

namespace fw::behavior {
namespace {

constexpr float kReach = 0.15f;

float falloff(float distance) {
  if (distance >= kReach) return 0.0f;
  const float t = distance / kReach;
  return (1.0f - t * t) * (1.0f - t * t);
}

std::set<std::uint32_t> vertices_of(const model::GenericFace& face, const std::vector<std::string>& regions) {
  std::set<model::FaceRegion> wanted;
  for (const std::string& name : regions)
    if (const auto r = model::face_region_from_name(name)) wanted.insert(*r);
  std::set<std::uint32_t> vertices;
  for (std::size_t f = 0; f < face.skin.triangles.size(); ++f)
    if (wanted.contains(face.triangle_regions[f]))
      for (int k = 0; k < 3; ++k) vertices.insert(face.skin.triangles[f][k]);
  return vertices;
}

}  // namespace

std::vector<std::uint32_t> region_control_points(const model::GenericFace& face,
                                                 const std::vector<std::string>& regions) {
  const std::set<std::uint32_t> set = vertices_of(face, regions);
  std::vector<std::uint32_t> points(set.begin(), set.end());
  std::sort(points.begin(), points.end(), [&](std::uint32_t a, std::uint32_t b) {
    const glm::vec3 pa = face.skin.positions[a], pb = face.skin.positions[b];
    return pa.x != pb.x ? pa.x < pb.x : pa.y > pb.y;
  });
  return points;
}

std::optional<model::Morph> au_definition_morph(const script::AuDefinition& definition,
                                                const model::GenericFace& face, std::string& error,
                                                float model_units_per_unit) {
  struct Handle {
    glm::vec3 at, displacement;
  };
  std::vector<Handle> handles;
  std::set<std::uint32_t> movable;
  for (const script::ControlPointDisplacement& d : definition.displacements) {
    const std::vector<std::uint32_t> points = region_control_points(face, d.face_regions);
    if (points.empty()) {
      error = "region " + d.region + " has no vertices on the generic face";
      return std::nullopt;
    }
    if (d.point < 0 || static_cast<std::size_t>(d.point) >= points.size()) {
      error = "region " + d.region + " has control points 0.." + std::to_string(points.size() - 1) + "; point " +
              std::to_string(d.point) + " does not exist";
      return std::nullopt;
    }
    const glm::vec3 displacement = glm::vec3(static_cast<float>(d.displacement[0]), static_cast<float>(d.displacement[1]),
                                             static_cast<float>(d.displacement[2])) * model_units_per_unit;
    handles.push_back({face.skin.positions[points[static_cast<std::size_t>(d.point)]], displacement});
    const std::set<std::uint32_t> region = vertices_of(face, d.face_regions);
    movable.insert(region.begin(), region.end());
  }
  model::Morph morph;
  morph.vertex_delta.assign(face.skin.positions.size(), glm::vec3(0.0f));
  morph.uv_delta.assign(face.skin.positions.size(), glm::vec2(0.0f));
  for (std::uint32_t v : movable) {
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (const Handle& h : handles) {
      const float w = falloff(glm::length(glm::vec2(face.skin.positions[v]) - glm::vec2(h.at)));
      sum += w * h.displacement;
      weight += w;
    }
    morph.vertex_delta[v] = sum / std::max(1.0f, weight);
  }
  return morph;
}

}  // namespace fw::behavior
