#include "fw/model/motion_cloning.hpp"

#include <cassert>
#include <cmath>
#include <set>

#include <glm/matrix.hpp>

namespace fw::model {

std::vector<glm::mat2> fit_jacobians(const Mesh& generic_skin, std::span<const glm::vec2> fitted_xy) {
  const std::size_t n = generic_skin.positions.size();
  assert(fitted_xy.size() == n);
  std::vector<std::set<std::uint32_t>> neighbours(n);
  for (const glm::uvec3& t : generic_skin.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].insert(t[(k + 1) % 3]);
      neighbours[t[k]].insert(t[(k + 2) % 3]);
    }
  std::vector<glm::mat2> jacobians(n, glm::mat2(1.0f));
  for (std::size_t v = 0; v < n; ++v) {
    // J = (sum f e^T)(sum e e^T)^-1 minimises sum |J e - f|^2 over the edges.
    glm::mat2 fe(0.0f), ee(0.0f);
    for (std::uint32_t u : neighbours[v]) {
      const glm::vec2 e = glm::vec2(generic_skin.positions[u]) - glm::vec2(generic_skin.positions[v]);
      const glm::vec2 f = fitted_xy[u] - fitted_xy[v];
      fe += glm::outerProduct(f, e);
      ee += glm::outerProduct(e, e);
    }
    if (neighbours[v].size() >= 2 && std::abs(glm::determinant(ee)) > 1e-8f) jacobians[v] = fe * glm::inverse(ee);
  }
  return jacobians;
}

Morph clone_morph(const Morph& generic, std::span<const glm::mat2> jacobians) {
  assert(generic.vertex_delta.size() == jacobians.size());
  Morph cloned;
  cloned.vertex_delta.resize(generic.vertex_delta.size());
  cloned.uv_delta.resize(generic.uv_delta.size());
  for (std::size_t v = 0; v < jacobians.size(); ++v) {
    const glm::mat2& j = jacobians[v];
    const glm::vec3 d = generic.vertex_delta[v];
    const float depth_scale = std::sqrt(std::abs(glm::determinant(j)));
    cloned.vertex_delta[v] = glm::vec3(j * glm::vec2(d), d.z * depth_scale);
    // UVs are a linear function of x and y on every face, so their slide maps alike.
    if (v < generic.uv_delta.size()) cloned.uv_delta[v] = j * generic.uv_delta[v];
  }
  return cloned;
}

}  // namespace fw::model
