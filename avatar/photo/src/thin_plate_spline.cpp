#include "thin_plate_spline.hpp"

#include <cmath>

#include <opencv2/core.hpp>

namespace fw::photo {
namespace {

// The 2-D biharmonic kernel U(r) = r^2 log r^2 (written with r^2 to avoid a sqrt).
double kernel(glm::vec2 a, glm::vec2 b) {
  const double r2 = static_cast<double>((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y));
  return r2 > 1e-12 ? r2 * std::log(r2) : 0.0;
}

}  // namespace

bool ThinPlateSpline::fit(std::span<const glm::vec2> from, std::span<const glm::vec2> to, float regularization) {
  const int n = static_cast<int>(from.size());
  if (n < 3 || to.size() != from.size()) return false;
  // [K + lambda I, P; P^T, 0] [w; a] = [v; 0], P = [1 x y].
  cv::Mat system = cv::Mat::zeros(n + 3, n + 3, CV_64F);
  cv::Mat rhs = cv::Mat::zeros(n + 3, 2, CV_64F);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) system.at<double>(i, j) = kernel(from[static_cast<std::size_t>(i)], from[static_cast<std::size_t>(j)]);
    system.at<double>(i, i) += regularization;
    const glm::vec2 p = from[static_cast<std::size_t>(i)];
    const double row[3] = {1.0, p.x, p.y};
    for (int k = 0; k < 3; ++k) system.at<double>(i, n + k) = system.at<double>(n + k, i) = row[k];
    rhs.at<double>(i, 0) = to[static_cast<std::size_t>(i)].x;
    rhs.at<double>(i, 1) = to[static_cast<std::size_t>(i)].y;
  }
  cv::Mat solution;
  if (!cv::solve(system, rhs, solution, cv::DECOMP_LU)) return false;
  centres_.assign(from.begin(), from.end());
  weights_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    weights_[static_cast<std::size_t>(i)] = {solution.at<double>(i, 0), solution.at<double>(i, 1)};
  affine_c_ = {solution.at<double>(n, 0), solution.at<double>(n, 1)};
  affine_x_ = {solution.at<double>(n + 1, 0), solution.at<double>(n + 1, 1)};
  affine_y_ = {solution.at<double>(n + 2, 0), solution.at<double>(n + 2, 1)};
  return true;
}

glm::vec2 ThinPlateSpline::operator()(glm::vec2 p) const {
  glm::dvec2 sum = glm::dvec2(affine_c_) + glm::dvec2(affine_x_) * static_cast<double>(p.x) +
                   glm::dvec2(affine_y_) * static_cast<double>(p.y);
  for (std::size_t i = 0; i < centres_.size(); ++i) sum += glm::dvec2(weights_[i]) * kernel(p, centres_[i]);
  return glm::vec2(sum);
}

}  // namespace fw::photo
