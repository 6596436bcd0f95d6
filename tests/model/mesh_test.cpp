#include "fw/model/mesh.hpp"

#include <algorithm>

#include <gtest/gtest.h>

namespace fw::model {
namespace {

// A unit square of two triangles with a square hole made of a ring of eight.
Mesh square_with_hole() {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  mesh.uvs.resize(mesh.positions.size());
  mesh.triangles = {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  return mesh;
}

TEST(Mesh, NormalsOfAFlatMeshFaceTheViewer) {
  for (const glm::vec3& n : vertex_normals(square_with_hole())) {
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  }
}

TEST(Mesh, UnusedVertexHasZeroNormal) {
  Mesh mesh = square_with_hole();
  mesh.positions.push_back({9, 9, 9});
  EXPECT_EQ(vertex_normals(mesh).back(), glm::vec3(0.0f));
}

TEST(Mesh, FindsOuterLoopAndHole) {
  auto loops = boundary_loops(square_with_hole());
  ASSERT_EQ(loops.size(), 2u);
  std::sort(loops.begin(), loops.end(), [](auto& a, auto& b) { return a.front() < b.front(); });
  EXPECT_EQ(loops[0].size(), 4u);
  EXPECT_EQ(loops[1].size(), 4u);
  EXPECT_LT(*std::max_element(loops[0].begin(), loops[0].end()), 4u) << "outer loop: the corners";
  EXPECT_GE(*std::min_element(loops[1].begin(), loops[1].end()), 4u) << "inner loop: the hole";
}

TEST(Mesh, ClosedMeshHasNoBoundary) {
  Mesh tetrahedron;
  tetrahedron.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  EXPECT_TRUE(boundary_loops(tetrahedron).empty());
}

}  // namespace
}  // namespace fw::model
