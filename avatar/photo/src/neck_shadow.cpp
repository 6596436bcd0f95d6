#include "neck_shadow.hpp"

#include <algorithm>
#include <cmath>

#include "face_alignment.hpp"
#include "soft_inside.hpp"

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
// How far above the jaw line the shadow begins (model units), and over how
// many texels (per 320) it fades out into the person's own colours.
constexpr float kShadowOnset = 0.03f;
constexpr int kSoftTexelsPer320 = 2;
// Over how far (model units) beside the jaw's lower part it fades out.
constexpr float kSideFade = 0.15f;

float smoothstep(float x) {
  const float t = std::clamp(x, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The jaw line at x: its height, and how far x lies beside the jaw's lower
// part (0 under it; beside it the line keeps its end's height).
struct JawLine {
  float y = 0, beside = 0;
};

JawLine jaw_at(const ModelLandmarks& l, float x) {
  for (int i = kJawFirst; i < kJawLast; ++i) {
    const glm::vec2 a = l[static_cast<std::size_t>(i)], b = l[static_cast<std::size_t>(i + 1)];
    if ((x - a.x) * (x - b.x) > 0.0f || a.x == b.x) continue;
    return {a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x), 0.0f};
  }
  const glm::vec2 first = l[kJawFirst], last = l[kJawLast];
  const glm::vec2 end = std::abs(x - first.x) < std::abs(x - last.x) ? first : last;
  return {end.y, std::abs(x - end.x)};
}

}  // namespace

void shade_neck(cv::Mat& bgra, const cv::Mat& matte, const ModelLandmarks& landmarks,
                const model::TextureFrame& frame) {
  const int size = bgra.cols;
  // The shadow fades out over a few texels inside the person's own colours
  // rather than stopping at the matte's ragged edge (soft_inside.hpp).
  const cv::Mat own = soft_inside(matte >= kOwnColour, std::max(1, kSoftTexelsPer320 * size / 320));
  for (int col = 0; col < size; ++col) {
    const glm::vec2 top = texture_px_to_model(cv::Point2f(static_cast<float>(col), 0.0f), frame, size);
    const JawLine jaw = jaw_at(landmarks, top.x);
    // Beside the jaw the shadow fades out rather than stopping at a
    // vertical edge, which a turned head shows on its cheek.
    const float along = 1.0f - smoothstep(jaw.beside / kSideFade);
    if (along <= 0.0f) continue;
    for (int row = 0; row < size; ++row) {
      const float own_colour = own.at<float>(row, col);
      if (own_colour >= 1.0f) continue;
      const float y = texture_px_to_model(cv::Point2f(0.0f, static_cast<float>(row)), frame, size).y;
      const float below = jaw.y - y;
      if (below < -kShadowOnset) continue;
      // Into the shadow over a short way above the jaw line, not at a step.
      const float onset = smoothstep((below + kShadowOnset) / kShadowOnset);
      const float cast = kShadowAtJaw + (kShadowBelow - kShadowAtJaw) * smoothstep(below / kShadowDepth);
      const float shade = 1.0f + (cast - 1.0f) * onset * along * (1.0f - own_colour);
      cv::Vec4b& texel = bgra.at<cv::Vec4b>(row, col);
      for (int c = 0; c < 3; ++c) texel[c] = cv::saturate_cast<std::uint8_t>(texel[c] * shade);
    }
  }
}

}  // namespace fw::photo
