#pragma once
// A triangle mesh as the renderer and the asset file hold it.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace fw::model {

struct Mesh {
  std::vector<glm::vec3> positions;   ///< #V, model units
  std::vector<glm::vec2> uvs;         ///< #V, texture coordinates in [0,1], v up
  std::vector<glm::uvec3> triangles;  ///< #F, counter-clockwise seen from outside
};

/// Area-weighted vertex normals.
/// @param[in] mesh  positions and triangles
/// @return #V unit normals (zero for a vertex no triangle uses)
std::vector<glm::vec3> vertex_normals(const Mesh& mesh);

/// vertex_normals, with vertices at exactly the same position sharing one
/// normal: copies of a vertex that exist only for a texture seam (the head
/// shell's poles and silhouette) must not crease its shading. Sorts the
/// positions: for meshes whose normals are made once, not every frame.
std::vector<glm::vec3> welded_vertex_normals(const Mesh& mesh);

/// The closed boundary loops of a mesh whose triangles are consistently
/// wound, each in the direction its triangles traverse it. A loop is a list of
/// vertex indices without repeating the first. Empty if the mesh is closed;
/// edges shared by more than two triangles are not boundary edges.
std::vector<std::vector<std::uint32_t>> boundary_loops(const Mesh& mesh);

}  // namespace fw::model
