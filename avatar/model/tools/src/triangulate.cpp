#include "triangulate.hpp"

#include <stdexcept>
#include <string>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace fw::facegen {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<unsigned, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Storage = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// No_constraint_intersection_tag: crossing constraints throw instead of
// silently inventing intersection vertices.
using Triangulation =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, Storage, CGAL::No_constraint_intersection_tag>;

}  // namespace

std::vector<glm::uvec3> constrained_delaunay(const std::vector<glm::vec2>& points,
                                             const std::vector<std::pair<unsigned, unsigned>>& constraints) {
  Triangulation triangulation;
  std::vector<Triangulation::Vertex_handle> handles;
  handles.reserve(points.size());
  for (unsigned i = 0; i < points.size(); ++i) {
    handles.push_back(triangulation.insert(Kernel::Point_2(points[i].x, points[i].y)));
    handles.back()->info() = i;
  }
  if (triangulation.number_of_vertices() != points.size())
    throw std::runtime_error("facegen: two generated points coincide");
  try {
    for (const auto& [a, b] : constraints) triangulation.insert_constraint(handles[a], handles[b]);
  } catch (const CGAL::Failure_exception& e) {
    throw std::runtime_error(std::string("facegen: constraints cross: ") + e.what());
  }

  std::vector<glm::uvec3> triangles;
  for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end(); ++face)
    triangles.emplace_back(face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info());
  return triangles;
}

}  // namespace fw::facegen
