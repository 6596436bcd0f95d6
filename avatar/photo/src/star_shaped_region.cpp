#include "star_shaped_region.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace fw::photo {
namespace {

cv::Point2f direction(int k, int rays) {
  const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / static_cast<float>(rays);
  return {std::cos(a), -std::sin(a)};  // rows run down
}

}  // namespace

cv::Mat fill_holes(const cv::Mat& region) {
  // Flood the outside from a border one pixel wide: what it does not reach is inside.
  cv::Mat padded;
  cv::copyMakeBorder(region, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  cv::floodFill(padded, cv::Point(0, 0), cv::Scalar(128));
  cv::Mat filled = padded(cv::Rect(1, 1, region.cols, region.rows)) != 128;
  return filled;
}

std::vector<float> ray_reach(const cv::Mat& region, cv::Point2f centre, int rays, float max_gap) {
  std::vector<float> reach(static_cast<std::size_t>(rays), 0.0f);
  const float longest = std::hypot(static_cast<float>(region.cols), static_cast<float>(region.rows));
  for (int k = 0; k < rays; ++k) {
    const cv::Point2f d = direction(k, rays);
    float last_inside = -1.0f;
    for (float r = 0.0f; r < longest; r += 0.5f) {
      const cv::Point2f p = centre + r * d;
      const int x = static_cast<int>(std::lround(p.x)), y = static_cast<int>(std::lround(p.y));
      if (x < 0 || y < 0 || x >= region.cols || y >= region.rows) break;
      if (region.at<std::uint8_t>(y, x) != 0) {
        if (last_inside < 0.0f && r > 0.0f) break;  // the centre is outside: nothing to follow
        last_inside = r;
      } else if (last_inside < 0.0f || r - last_inside > max_gap) {
        break;
      }
    }
    reach[static_cast<std::size_t>(k)] = std::max(last_inside, 0.0f);
  }
  return reach;
}

std::vector<float> median_across_rays(const std::vector<float>& reach, int half_window) {
  const int n = static_cast<int>(reach.size());
  std::vector<float> out(reach.size()), window;
  for (int k = 0; k < n; ++k) {
    window.clear();
    for (int j = -half_window; j <= half_window; ++j)
      window.push_back(reach[static_cast<std::size_t>(((k + j) % n + n) % n)]);
    std::nth_element(window.begin(), window.begin() + half_window, window.end());
    out[static_cast<std::size_t>(k)] = window[static_cast<std::size_t>(half_window)];
  }
  return out;
}

cv::Mat fill_reach(const std::vector<float>& reach, cv::Point2f centre, cv::Size size, float scale) {
  // Sub-pixel vertices: fillPoly's shift keeps the outline as smooth as the reaches.
  constexpr int kShift = 4;
  const float unit = static_cast<float>(1 << kShift);
  std::vector<cv::Point> polygon;
  const int rays = static_cast<int>(reach.size());
  for (int k = 0; k < rays; ++k) {
    const cv::Point2f p = scale * (centre + reach[static_cast<std::size_t>(k)] * direction(k, rays));
    polygon.emplace_back(static_cast<int>(std::lround(p.x * unit)), static_cast<int>(std::lround(p.y * unit)));
  }
  cv::Mat filled(size, CV_8U, cv::Scalar(0));
  cv::fillPoly(filled, std::vector{polygon}, cv::Scalar(255), cv::LINE_8, kShift);
  return filled;
}

}  // namespace fw::photo
