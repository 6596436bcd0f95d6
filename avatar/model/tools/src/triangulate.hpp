#pragma once
// Constrained Delaunay triangulation of the face's point set (CGAL).
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace fw::facegen {

/// Triangulates `points` so that every segment in `constraints` (pairs of
/// point indices) is an edge. Returns all finite triangles, counter-clockwise.
/// Throws std::runtime_error if constraints cross (the generator's points
/// are wrong), since a crossing would add vertices that have no landmark or UV.
std::vector<glm::uvec3> constrained_delaunay(const std::vector<glm::vec2>& points,
                                             const std::vector<std::pair<unsigned, unsigned>>& constraints);

}  // namespace fw::facegen
