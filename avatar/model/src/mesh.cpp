#include "fw/model/mesh.hpp"

#include <map>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>

namespace fw::model {

namespace {

// Each vertex's sum of its triangles' cross products, not yet unit length.
std::vector<glm::vec3> area_weighted_sums(const Mesh& mesh) {
  std::vector<glm::vec3> sums(mesh.positions.size(), glm::vec3(0.0f));
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3& a = mesh.positions[t.x];
    const glm::vec3& b = mesh.positions[t.y];
    const glm::vec3& c = mesh.positions[t.z];
    // The cross product's length is twice the area: larger faces weigh more.
    const glm::vec3 n = glm::cross(b - a, c - a);
    sums[t.x] += n;
    sums[t.y] += n;
    sums[t.z] += n;
  }
  return sums;
}

std::vector<glm::vec3> unit_lengths(std::vector<glm::vec3> normals) {
  for (glm::vec3& n : normals) {
    const float length = glm::length(n);
    if (length > 0.0f) n /= length;
  }
  return normals;
}

}  // namespace

std::vector<glm::vec3> vertex_normals(const Mesh& mesh) { return unit_lengths(area_weighted_sums(mesh)); }

std::vector<glm::vec3> welded_vertex_normals(const Mesh& mesh) {
  std::vector<glm::vec3> normals = area_weighted_sums(mesh);
  const auto key = [](const glm::vec3& p) { return std::tuple(p.x, p.y, p.z); };
  std::map<std::tuple<float, float, float>, glm::vec3> welded;
  for (std::size_t v = 0; v < normals.size(); ++v) welded[key(mesh.positions[v])] += normals[v];
  for (std::size_t v = 0; v < normals.size(); ++v) normals[v] = welded[key(mesh.positions[v])];
  return unit_lengths(std::move(normals));
}

std::vector<std::vector<std::uint32_t>> boundary_loops(const Mesh& mesh) {
  // A directed edge whose reverse no triangle uses lies on the boundary.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];

  std::map<std::uint32_t, std::uint32_t> next;  // boundary edge start -> end
  for (const auto& [edge, count] : directed)
    if (count == 1 && !directed.contains({edge.second, edge.first})) next[edge.first] = edge.second;

  std::vector<std::vector<std::uint32_t>> loops;
  while (!next.empty()) {
    std::vector<std::uint32_t> loop;
    std::uint32_t v = next.begin()->first;
    while (true) {
      auto it = next.find(v);
      if (it == next.end()) break;  // open chain: a non-manifold boundary, stop here
      loop.push_back(v);
      v = it->second;
      next.erase(it);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace fw::model
