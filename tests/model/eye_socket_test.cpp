// The eye sockets (fw/model/eye_socket.hpp): every line of sight through an
// eye hole meets the eyeball or the socket's far wall, at every expression,
// and the wall shows the eye's white, never its iris.
#include "fw/model/eye_socket.hpp"

#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/model/face_asset.hpp"
#include "fw/model/fitted_face.hpp"

namespace fw::model {
namespace {

// A line of sight through a point inside a closed sphere leaves it through
// the sphere's far wall: the socket holds the hole if every point of the
// hole is inside it. The hole's points are its rim's vertices (it is a
// polygon between them).
void expect_hole_inside(const GenericFace& face, std::span<const glm::vec3> positions, const std::string& what) {
  for (std::size_t side = 0; side < 2; ++side) {
    const float radius = eye_socket_radius(face, side);
    for (const std::uint32_t v : face.eye_holes[side])
      EXPECT_LT(glm::length(positions[v] - face.eyes[side].centre), radius)
          << what << ": vertex " << v << " of eye hole " << side << " lies outside its socket";
  }
}

TEST(EyeSocket, HoldsTheWholeHoleAtRestAndAtEveryActionUnit) {
  const GenericFace& face = generic_face();
  expect_hole_inside(face, face.skin.positions, "at rest");
  for (std::size_t unit = 0; unit < face.action_units.size(); ++unit) {
    std::vector<glm::vec3> moved = face.skin.positions;
    const Morph& morph = face.action_units[unit];
    for (std::size_t v = 0; v < moved.size() && v < morph.vertex_delta.size(); ++v) moved[v] += morph.vertex_delta[v];
    expect_hole_inside(face, moved, "action unit channel " + std::to_string(unit) + " at full intensity");
  }
}

TEST(EyeSocket, HoldsTheHoleOfAFittedFace) {
  // A face fitted wider apart and taller than the generic one.
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : generic_face().skin.positions) xy.emplace_back(p.x * 1.15f, p.y * 1.1f);
  const GenericFace fitted = fit_generic_face(generic_face(), xy);
  expect_hole_inside(fitted, fitted.skin.positions, "fitted");
}

TEST(EyeSocket, IsAClosedSphereFacingOut) {
  const GenericFace& face = generic_face();
  for (std::size_t side = 0; side < 2; ++side) {
    const Mesh socket = eye_socket_mesh(face, side);
    const glm::vec3 centre = face.eyes[side].centre;
    const float radius = eye_socket_radius(face, side);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const glm::uvec3& t : socket.triangles) {
      const glm::vec3 a = socket.positions[t.x], b = socket.positions[t.y], c = socket.positions[t.z];
      // Facing out: a renderer that culls front faces shows the far wall.
      EXPECT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0f - centre), 0.0f);
      for (const auto& [p, q] : {std::pair{t.x, t.y}, std::pair{t.y, t.z}, std::pair{t.z, t.x}}) ++edges[{p, q}];
    }
    // Closed: every directed edge is matched by its reverse once.
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << "an open edge";
    }
    for (const glm::vec3& p : socket.positions) EXPECT_NEAR(glm::length(p - centre), radius, 1e-5f);
  }
}

TEST(EyeSocket, ShowsTheWhiteNeverTheIris) {
  const GenericFace& face = generic_face();
  const EyeLayer& eye = face.eyes[0];
  // The iris: 5.85 mm on the globe (procedural_texture.cpp), an angle
  // of asin(5.85 / 12) from the front pole; its uv radius in the polar map.
  const float iris_uv = 0.5f * std::asin(5.85f / kMillimetresPerUnit / eye.radius) / eye.cap_angle_rad;
  for (const glm::vec2 uv : eye_socket_mesh(face, 0).uvs) EXPECT_GT(glm::length(uv - glm::vec2(0.5f)), 1.2f * iris_uv);
}

}  // namespace
}  // namespace fw::model
