#include "texture_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

#include "soft_inside.hpp"

namespace fw::photo {
namespace {

// A texel counts as seen when the surface faces the camera at least this
// share as much as it would facing it head-on; fully below the first,
// fully above the second.
constexpr float kSeenFrom = 0.35f, kSeenFully = 0.75f;
// How far (model units) a texel may lie behind the nearest surface at its
// place in the photo and still count as in front.
constexpr float kOcclusionSlack = 0.06f;
// A mirror texel counts as the person's where the matte is at least this.
constexpr int kMirrorOnPerson = 250, kMirrorEdgeTexelsPer320 = 3;

float smoothstep(float from, float to, float x) {
  const float t = std::clamp((x - from) / (to - from), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The photo sampled at each texel's point, and how well the photo sees it.
struct Sampled {
  cv::Mat photo;         // BGR, `size` x `size`
  cv::Mat seen;          // CV_32F, 0 (turned away or hidden) .. 1
  cv::Mat map_x, map_y;  // where each texel lies in the photo sampled
  cv::Size photo_size;   // of the photo sampled
};

Sampled sample_through_pose(const cv::Mat& full_photo, const Alignment& full_alignment, const PoseFit& fit,
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
  return {sampled, seen, map_x, map_y, sampling.photo.size()};
}

}  // namespace

PhotoAtTexels photo_at_texels(const cv::Mat& photo, const Alignment& alignment, const PoseFit& fit,
                              const model::TextureFrame& frame, int size) {
  const Sampled sampled = sample_through_pose(photo, alignment, fit, frame, size);
  PhotoAtTexels out{sampled.photo, {}};
  cv::remap(cv::Mat(sampled.photo_size, CV_8U, cv::Scalar(255)), out.in_photo, sampled.map_x, sampled.map_y,
            cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  return out;
}

cv::Mat extract_texture(const cv::Mat& photo, const Alignment& alignment, const PoseFit& fit,
                        const model::TextureFrame& frame, int size) {
  const Sampled sampled_photo = sample_through_pose(photo, alignment, fit, frame, size);
  const cv::Mat& sampled = sampled_photo.photo;
  const cv::Mat& seen = sampled_photo.seen;
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

cv::Mat mirror_only_within(const cv::Mat& texture, const cv::Mat& seen, const cv::Mat& matte) {
  cv::Mat mirrored;
  cv::flip(matte, mirrored, 1);  // the texture frame is centred on the face's midline
  // Not the last texels along the edge either (those mix hair with what
  // stood behind it), and blended over a few more: switched at the mirrored
  // matte's ragged edge, the mirror showed its steps along the jaw.
  const int edge = std::max(1, kMirrorEdgeTexelsPer320 * texture.cols / 320);
  const cv::Mat weight = soft_inside(mirrored >= kMirrorOnPerson, edge);
  cv::Mat mirror, own, weight3;
  texture.convertTo(mirror, CV_32FC3);
  seen.convertTo(own, CV_32FC3);
  cv::merge(std::vector<cv::Mat>{weight, weight, weight}, weight3);
  const cv::Mat blended = own + (mirror - own).mul(weight3);
  cv::Mat out;
  blended.convertTo(out, texture.type());
  return out;
}

}  // namespace fw::photo
