#pragma once
// A 2-D thin-plate spline: the smoothest map (least bending energy) that
// takes a set of points to another, here the template landmarks to a
// person's. Bookstein, "Principal warps", 1989.
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace fw::photo {

class ThinPlateSpline {
 public:
  /// Fits f with f(from[i]) ~ to[i]. `regularization` (>= 0, in squared
  /// model units) trades exactness for smoothness; 0 interpolates exactly.
  /// @return false if the points are degenerate (fewer than 3, or collinear)
  bool fit(std::span<const glm::vec2> from, std::span<const glm::vec2> to, float regularization);
  glm::vec2 operator()(glm::vec2 p) const;

 private:
  std::vector<glm::vec2> centres_;
  std::vector<glm::vec2> weights_;  ///< one per centre
  glm::vec2 affine_c_{0.0f}, affine_x_{1.0f, 0.0f}, affine_y_{0.0f, 1.0f};
};

}  // namespace fw::photo
