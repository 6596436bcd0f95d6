#include "texture_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

namespace fw::photo {
namespace {

// A texel counts as seen when the surface faces the camera at least this
// share as much as it would facing it head-on; fully below the first,
// fully above the second.
constexpr float kSeenFrom = 0.35f, kSeenFully = 0.75f;
// How far (model units) a texel may lie behind the nearest surface at its
// place in the photo and still count as in front.
constexpr float kOcclusionSlack = 0.06f;

float smoothstep(float from, float to, float x) {
  const float t = std::clamp((x - from) / (to - from), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

}  // namespace

cv::Mat extract_texture(const cv::Mat& full_photo, const Alignment& full_alignment, const PoseFit& fit,
                        const model::TextureFrame& frame, int size) {
  const PhotoForSampling sampling = photo_for_sampling(full_photo, full_alignment, frame, size);
  const HeadPose& pose = fit.pose;
  // The surface point behind each texel; its normal from the neighbours'.
  std::vector<glm::vec3> points(static_cast<std::size_t>(size) * size);
  const auto at = [&](int row, int col) -> glm::vec3& {
    return points[static_cast<std::size_t>(std::clamp(row, 0, size - 1)) * size + std::clamp(col, 0, size - 1)];
  };
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col)
      at(row, col) = fit.surface(texture_px_to_model(cv::Point2f(float(col), float(row)), frame, size));

  cv::Mat map_x(size, size, CV_32F), map_y(size, size, CV_32F);
  cv::Mat seen(size, size, CV_32F), depth(size, size, CV_32F);
  std::vector<cv::Point2f> in_image(static_cast<std::size_t>(size) * size);
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const glm::vec3 point = at(row, col);
      const glm::vec2 q = pose.project(point);
      const glm::vec2 px = sampling.alignment.to_photo(q);
      map_x.at<float>(row, col) = px.x;
      map_y.at<float>(row, col) = px.y;
      // Texture rows run down, the model's y up.
      const glm::vec3 normal = glm::normalize(
          glm::cross(at(row, col + 1) - at(row, col - 1), at(row - 1, col) - at(row + 1, col)));
      const float head_on = std::max(normal.z, 1e-3f);
      seen.at<float>(row, col) = smoothstep(kSeenFrom, kSeenFully, pose.facing(normal) / head_on);
      depth.at<float>(row, col) = (pose.rotation * point).z;
      in_image[static_cast<std::size_t>(row) * size + col] = {q.x, q.y};
    }

  // Hidden surface: the nearest depth at each place of the image plane, on
  // a grid as fine as the texture, widened by a cell to close gaps.
  const float cells_per_unit = static_cast<float>(size) / frame.size;
  cv::Mat nearest(size, size, CV_32F, cv::Scalar(-std::numeric_limits<float>::infinity()));
  const auto cell = [&](cv::Point2f q) {
    return cv::Point(static_cast<int>((q.x - frame.origin.x) * cells_per_unit),
                     static_cast<int>((frame.origin.y + frame.size - q.y) * cells_per_unit));
  };
  const cv::Rect grid(0, 0, size, size);
  for (int i = 0; i < size * size; ++i) {
    const cv::Point c = cell(in_image[static_cast<std::size_t>(i)]);
    if (grid.contains(c)) nearest.at<float>(c) = std::max(nearest.at<float>(c), depth.at<float>(i / size, i % size));
  }
  cv::dilate(nearest, nearest, cv::Mat::ones(3, 3, CV_8U));
  for (int i = 0; i < size * size; ++i) {
    const cv::Point c = cell(in_image[static_cast<std::size_t>(i)]);
    if (grid.contains(c) && depth.at<float>(i / size, i % size) < nearest.at<float>(c) - kOcclusionSlack)
      seen.at<float>(i / size, i % size) = 0.0f;
  }

  cv::Mat sampled;
  cv::remap(sampling.photo, sampled, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  // Fill from the mirror image where this side is seen worse than that one.
  cv::Mat texture = sampled.clone();
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const glm::vec2 p = texture_px_to_model(cv::Point2f(float(col), float(row)), frame, size);
      const cv::Point2f mirror = model_to_texture_px({-p.x, p.y}, frame, size);
      const int mc = std::clamp(static_cast<int>(std::lround(mirror.x)), 0, size - 1);
      const float w = seen.at<float>(row, col);
      const float w_mirror = (1.0f - w) * seen.at<float>(row, mc);
      if (w >= 0.999f || w + w_mirror < 0.05f) continue;
      const cv::Vec3f own = sampled.at<cv::Vec3b>(row, col), other = sampled.at<cv::Vec3b>(row, mc);
      texture.at<cv::Vec3b>(row, col) = (own * w + other * w_mirror) / (w + w_mirror);
    }
  return texture;
}

}  // namespace fw::photo
