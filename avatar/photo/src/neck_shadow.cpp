#include "neck_shadow.hpp"

#include <algorithm>
#include <optional>

#include "face_alignment.hpp"

namespace fw::photo {
namespace {

// Brightness right under the jaw line and at kShadowDepth (model units)
// below it. Set by eye on the test portraits and against the Likeness test:
// with the neck lit like the jaw, dlib lost Grace Hopper's jaw line (median
// error 0.050 inter-ocular, against 0.031 with this shade).
constexpr float kShadowAtJaw = 0.55f, kShadowBelow = 0.8f, kShadowDepth = 0.35f;
constexpr int kJawFirst = 3, kJawLast = 13;
// What the matte keeps as the person's own colour is not shaded.
constexpr int kOwnColour = 250;

float smoothstep(float x) {
  const float t = std::clamp(x, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The jaw line's height at x, or nothing beside the jaw's lower part.
std::optional<float> jaw_at(const ModelLandmarks& l, float x) {
  for (int i = kJawFirst; i < kJawLast; ++i) {
    const glm::vec2 a = l[static_cast<std::size_t>(i)], b = l[static_cast<std::size_t>(i + 1)];
    if ((x - a.x) * (x - b.x) > 0.0f || a.x == b.x) continue;
    return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
  }
  return std::nullopt;
}

}  // namespace

void shade_neck(cv::Mat& bgra, const cv::Mat& matte, const ModelLandmarks& landmarks,
                const model::TextureFrame& frame) {
  const int size = bgra.cols;
  for (int col = 0; col < size; ++col) {
    const glm::vec2 top = texture_px_to_model(cv::Point2f(static_cast<float>(col), 0.0f), frame, size);
    const std::optional<float> jaw = jaw_at(landmarks, top.x);
    if (!jaw) continue;
    for (int row = 0; row < size; ++row) {
      if (matte.at<std::uint8_t>(row, col) >= kOwnColour) continue;
      const float y = texture_px_to_model(cv::Point2f(0.0f, static_cast<float>(row)), frame, size).y;
      const float below = *jaw - y;
      if (below < 0.0f) continue;
      const float shade = kShadowAtJaw + (kShadowBelow - kShadowAtJaw) * smoothstep(below / kShadowDepth);
      cv::Vec4b& texel = bgra.at<cv::Vec4b>(row, col);
      for (int c = 0; c < 3; ++c) texel[c] = cv::saturate_cast<std::uint8_t>(texel[c] * shade);
    }
  }
}

}  // namespace fw::photo
