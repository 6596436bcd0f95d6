#include "fw/model/eye_socket.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace fw::model {
namespace {

// Past the hole's farthest vertex from the eyeball's centre: the lids move
// (a wide-eyed upper lid rises by about 2 mm, AU 5) and the hole must stay
// inside at every expression.
constexpr float kMargin = 1.25f;
// Never smaller than this many eyeball radii, so that the far wall lies
// well behind the eyeball however it turns.
constexpr float kLeastRadii = 1.3f;
// The wall's uvs map it onto the eye texture as the eyeball's own (the
// angle from the front pole), so that it continues the eyeball's white and
// its darkening toward the corners; never nearer the pole than this, where
// the iris is (5.85 mm on a 12 mm globe: 0.5 rad).
constexpr float kLeastAngle = 0.75f;
// A coarse sphere: it is seen only through the hole, from inside, and
// every triangle costs a software renderer (two eyes to a face).
constexpr int kRings = 8, kSegments = 12;

}  // namespace

float eye_socket_radius(const GenericFace& face, std::size_t side) {
  const EyeLayer& eye = face.eyes[side];
  float reach = kLeastRadii * eye.radius;
  for (const std::uint32_t v : face.eye_holes[side])
    reach = std::max(reach, kMargin * glm::length(face.skin.positions[v] - eye.centre));
  return reach;
}

Mesh eye_socket_mesh(const GenericFace& face, std::size_t side) {
  const EyeLayer& eye = face.eyes[side];
  const float radius = eye_socket_radius(face, side);
  Mesh mesh;
  const float pi = std::numbers::pi_v<float>;
  // Poles on the z axis, rings between them.
  mesh.positions.push_back(eye.centre + glm::vec3(0.0f, 0.0f, radius));
  for (int ring = 1; ring < kRings; ++ring) {
    const float theta = pi * static_cast<float>(ring) / kRings;
    for (int s = 0; s < kSegments; ++s) {
      const float phi = 2.0f * pi * static_cast<float>(s) / kSegments;
      mesh.positions.push_back(eye.centre + radius * glm::vec3(std::sin(theta) * std::cos(phi),
                                                               std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  }
  mesh.positions.push_back(eye.centre - glm::vec3(0.0f, 0.0f, radius));
  for (const glm::vec3& p : mesh.positions) {
    const glm::vec3 d = (p - eye.centre) / radius;
    const float angle = std::clamp(std::acos(std::clamp(d.z, -1.0f, 1.0f)), kLeastAngle, eye.cap_angle_rad);
    const float around = std::atan2(d.y, d.x);
    const float r = eye.cap_angle_rad > 0.0f ? 0.5f * angle / eye.cap_angle_rad : 0.0f;
    mesh.uvs.emplace_back(0.5f + r * std::cos(around), 0.5f + r * std::sin(around));
  }
  const auto at = [](int ring, int s) {
    return static_cast<std::uint32_t>(1 + (ring - 1) * kSegments + ((s % kSegments) + kSegments) % kSegments);
  };
  const auto last = static_cast<std::uint32_t>(mesh.positions.size() - 1);
  for (int s = 0; s < kSegments; ++s) {
    mesh.triangles.emplace_back(0u, at(1, s), at(1, s + 1));
    mesh.triangles.emplace_back(last, at(kRings - 1, s + 1), at(kRings - 1, s));
  }
  for (int ring = 1; ring + 1 < kRings; ++ring)
    for (int s = 0; s < kSegments; ++s) {
      mesh.triangles.emplace_back(at(ring, s), at(ring + 1, s), at(ring + 1, s + 1));
      mesh.triangles.emplace_back(at(ring, s), at(ring + 1, s + 1), at(ring, s + 1));
    }
  return mesh;
}

}  // namespace fw::model
