#include "face_alignment.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

namespace fw::photo {

glm::vec2 landmark_centre(const PhotoLandmarks& l, int begin, int end) {
  glm::vec2 sum(0.0f);
  for (int i = begin; i < end; ++i) sum += l[static_cast<std::size_t>(i)];
  return sum / static_cast<float>(end - begin);
}

glm::vec2 Alignment::to_model(glm::vec2 px) const {
  const glm::vec2 d = (px - eye_midpoint_px) / inter_ocular_px;
  const float c = std::cos(roll_rad), s = std::sin(roll_rad);
  // Undo the roll, then flip y (image rows run down, the model's y up).
  return {c * d.x + s * d.y, -(-s * d.x + c * d.y)};
}

glm::vec2 Alignment::to_photo(glm::vec2 m) const {
  const glm::vec2 d(m.x, -m.y);
  const float c = std::cos(roll_rad), s = std::sin(roll_rad);
  return eye_midpoint_px + inter_ocular_px * glm::vec2(c * d.x - s * d.y, s * d.x + c * d.y);
}

Alignment align_by_eyes(const PhotoLandmarks& landmarks) {
  namespace lm = model::landmarks;
  const glm::vec2 right = landmark_centre(landmarks, lm::kEyeRightBegin, lm::kEyeRightEnd);  // image left
  const glm::vec2 left = landmark_centre(landmarks, lm::kEyeLeftBegin, lm::kEyeLeftEnd);
  Alignment a;
  a.eye_midpoint_px = 0.5f * (left + right);
  const glm::vec2 d = left - right;
  a.inter_ocular_px = std::max(1e-3f, std::hypot(d.x, d.y));
  a.roll_rad = std::atan2(d.y, d.x);
  return a;
}

cv::Point2f model_to_texture_px(glm::vec2 p, const model::TextureFrame& frame, int size) {
  const glm::vec2 uv = frame.to_uv(p);
  return {uv.x * static_cast<float>(size) - 0.5f, (1.0f - uv.y) * static_cast<float>(size) - 0.5f};
}

glm::vec2 texture_px_to_model(cv::Point2f px, const model::TextureFrame& frame, int size) {
  return frame.to_model({(px.x + 0.5f) / static_cast<float>(size), 1.0f - (px.y + 0.5f) / static_cast<float>(size)});
}

PhotoForSampling photo_for_sampling(const cv::Mat& photo, const Alignment& alignment,
                                    const model::TextureFrame& frame, int size) {
  PhotoForSampling sampling{photo, alignment};
  const float texture_px_per_photo_px = static_cast<float>(size) / frame.size / alignment.inter_ocular_px;
  if (texture_px_per_photo_px < 0.5f) {
    const double f = 2.0 * texture_px_per_photo_px;
    cv::resize(photo, sampling.photo, cv::Size(), f, f, cv::INTER_AREA);
    sampling.alignment.eye_midpoint_px *= static_cast<float>(f);
    sampling.alignment.inter_ocular_px *= static_cast<float>(f);
  }
  return sampling;
}

cv::Mat warp_to_texture(const cv::Mat& full_photo, const Alignment& full_alignment, const model::TextureFrame& frame,
                        int size) {
  const PhotoForSampling sampling = photo_for_sampling(full_photo, full_alignment, frame, size);
  // The map texture px -> photo px is affine; three points fix it.
  const cv::Point2f texture[3] = {{0, 0}, {static_cast<float>(size), 0}, {0, static_cast<float>(size)}};
  cv::Point2f source[3];
  for (int i = 0; i < 3; ++i) {
    const glm::vec2 p = sampling.alignment.to_photo(texture_px_to_model(texture[i], frame, size));
    source[i] = {p.x, p.y};
  }
  const cv::Mat texture_to_photo = cv::getAffineTransform(texture, source);
  cv::Mat out;
  cv::warpAffine(sampling.photo, out, texture_to_photo, cv::Size(size, size), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 cv::BORDER_REPLICATE);
  return out;
}

}  // namespace fw::photo
