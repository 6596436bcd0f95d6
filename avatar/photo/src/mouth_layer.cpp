#include "mouth_layer.hpp"

#include <glm/common.hpp>
#include <opencv2/imgproc.hpp>

#include "face_alignment.hpp"
#include "fw/model/procedural_texture.hpp"
#include "image_conversion.hpp"

namespace fw::photo {
namespace {

constexpr int kWidth = 128, kHeight = 64;
constexpr int kSupersample = 4;

}  // namespace

cv::Mat make_mouth_layer(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::GenericFace& fitted) {
  glm::vec2 low(1e9f), high(-1e9f);
  for (const glm::vec3& p : fitted.mouth_cavity.positions) {
    low = glm::min(low, glm::vec2(p));
    high = glm::max(high, glm::vec2(p));
  }
  // Where each mouth-layer pixel lies on the face texture.
  cv::Mat map_x(kHeight, kWidth, CV_32F), map_y(kHeight, kWidth, CV_32F);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / kWidth, 1.0f - (static_cast<float>(y) + 0.5f) / kHeight);
      const cv::Point2f px = model_to_texture_px(low + uv * (high - low), fitted.texture_frame, texture.cols);
      map_x.at<float>(y, x) = px.x;
      map_y.at<float>(y, x) = px.y;
    }
  cv::Mat from_photo;
  cv::remap(texture, from_photo, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REPLICATE);

  // The opening between the inner lips, anti-aliased, in mouth-layer pixels.
  std::vector<cv::Point> opening;
  for (int i = model::landmarks::kInnerLipBegin; i < model::landmarks::kInnerLipEnd; ++i) {
    const glm::vec2 uv = (landmarks[static_cast<std::size_t>(i)] - low) / (high - low);
    opening.emplace_back(static_cast<int>(uv.x * kWidth * kSupersample), static_cast<int>((1.0f - uv.y) * kHeight * kSupersample));
  }
  cv::Mat big = cv::Mat::zeros(kHeight * kSupersample, kWidth * kSupersample, CV_8U);
  cv::fillPoly(big, std::vector<std::vector<cv::Point>>{opening}, cv::Scalar(255), cv::LINE_AA);
  cv::Mat coverage;
  cv::resize(big, coverage, cv::Size(kWidth, kHeight), 0, 0, cv::INTER_AREA);
  cv::GaussianBlur(coverage, coverage, cv::Size(5, 5), 1.0);

  const cv::Mat cavity = to_bgr_mat(model::make_mouth_texture(kWidth, kHeight));
  cv::Mat layer(kHeight, kWidth, CV_8UC3);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const float a = coverage.at<std::uint8_t>(y, x) / 255.0f;
      layer.at<cv::Vec3b>(y, x) = from_photo.at<cv::Vec3b>(y, x) * a + cavity.at<cv::Vec3b>(y, x) * (1.0f - a);
    }
  return layer;
}

}  // namespace fw::photo
