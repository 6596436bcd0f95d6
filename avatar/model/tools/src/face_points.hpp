#pragma once
// The 2-D point set and constraint polygons of the generic face, before
// triangulation. Private to the generator.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace fw::facegen {

struct FacePoints {
  std::vector<glm::vec2> points;                 ///< landmarks first (0..67), then the rest
  std::vector<std::uint32_t> outline;            ///< face outline (jaw, temples, hairline), CCW
  std::vector<std::uint32_t> rim;                ///< outer boundary of the mesh, CCW
  std::size_t first_rim_point = 0;               ///< points from here on are rim points
};

/// Places every vertex of the generic face in the model frame.
FacePoints place_face_points();

/// Polygon helpers shared by triangulation and region assignment.
bool inside_polygon(glm::vec2 p, const std::vector<glm::vec2>& polygon);
std::vector<glm::vec2> polygon_of(const FacePoints& face, const std::vector<std::uint32_t>& indices);
std::vector<glm::vec2> landmark_polygon(int begin, int end);

}  // namespace fw::facegen
