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
// Beside the jaw's lower part the shadow's edge rises as steeply as the
// jaw's ramus does toward the ear (seen from the front, the ramus stands
// nearly edge-on at the face's side), fading out over kSideFade (model
// units). Kept level there, the edge ran straight back across the side of
// a turned head as a ledge under the cheek.
constexpr float kRamusRise = 3.0f, kSideFade = 0.3f;
// Each texel takes the shadow averaged over this many points a side: where
// the jaw runs steeply, below the ear, the shadow's onset is a fraction of a
// texel wide across the jaw line. Taken at each texel's centre, each column
// went dark at once a few rows below its neighbour, a staircase that a turned
// head stretched along its jaw.
constexpr int kSamplesPerSide = 4;

float smoothstep(float x) {
  const float t = std::clamp(x, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The jaw line at x: its height, and how far x lies beside the jaw's lower
// part (0 under it; beside it the line rises from its end, kRamusRise).
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
  const float beside = std::abs(x - end.x);
  return {end.y + kRamusRise * beside, beside};
}

// How much the shadow takes off the brightness at p (model units): 0 above
// the jaw line and beside the jaw's lower part, 1 - kShadowAtJaw under it.
float darkening(const ModelLandmarks& l, glm::vec2 p) {
  const JawLine jaw = jaw_at(l, p.x);
  const float below = jaw.y - p.y;
  if (below < -kShadowOnset) return 0.0f;
  // Beside the jaw the shadow fades out rather than stopping at a
  // vertical edge, which a turned head shows on its cheek.
  const float along = 1.0f - smoothstep(jaw.beside / kSideFade);
  // Into the shadow over a short way above the jaw line, not at a step.
  const float onset = smoothstep((below + kShadowOnset) / kShadowOnset);
  const float cast = kShadowAtJaw + (kShadowBelow - kShadowAtJaw) * smoothstep(below / kShadowDepth);
  return (1.0f - cast) * onset * along;
}

// The darkening averaged over the texel's area.
float texel_darkening(const ModelLandmarks& l, int col, int row, const model::TextureFrame& frame, int size) {
  float sum = 0.0f;
  for (int i = 0; i < kSamplesPerSide; ++i)
    for (int j = 0; j < kSamplesPerSide; ++j) {
      const cv::Point2f offset((static_cast<float>(i) + 0.5f) / kSamplesPerSide - 0.5f,
                               (static_cast<float>(j) + 0.5f) / kSamplesPerSide - 0.5f);
      sum += darkening(l, texture_px_to_model(cv::Point2f(static_cast<float>(col), static_cast<float>(row)) + offset,
                                              frame, size));
    }
  return sum / (kSamplesPerSide * kSamplesPerSide);
}

}  // namespace

void shade_neck(cv::Mat& bgra, const cv::Mat& matte, const ModelLandmarks& landmarks,
                const model::TextureFrame& frame) {
  const int size = bgra.cols;
  // The shadow fades out over a few texels inside the person's own colours
  // rather than stopping at the matte's ragged edge (soft_inside.hpp).
  const cv::Mat own = soft_inside(matte >= kOwnColour, std::max(1, kSoftTexelsPer320 * size / 320));
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const float own_colour = own.at<float>(row, col);
      if (own_colour >= 1.0f) continue;
      const float shade = 1.0f - texel_darkening(landmarks, col, row, frame, size) * (1.0f - own_colour);
      if (shade >= 1.0f) continue;
      cv::Vec4b& texel = bgra.at<cv::Vec4b>(row, col);
      for (int c = 0; c < 3; ++c) texel[c] = cv::saturate_cast<std::uint8_t>(texel[c] * shade);
    }
}

}  // namespace fw::photo
