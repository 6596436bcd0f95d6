#include "outline_band.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "face_alignment.hpp"
#include "fw/model/head_shell.hpp"
#include "fw/model/srgb.hpp"

namespace fw::photo {
namespace {

constexpr float kFullTurn = 2.0f * std::numbers::pi_v<float>;
// Half the arc averaged at the silhouette: two rays' spacing either side.
constexpr float kWidestHalfArc = kFullTurn / 16.0f;
constexpr int kSamplesEachSide = 6;

}  // namespace

void smooth_outline_band(cv::Mat& bgra, std::span<const float> outline, std::span<const float> inner,
                         glm::vec2 centre, const model::TextureFrame& frame) {
  assert(bgra.type() == CV_8UC4 && outline.size() == inner.size() && !outline.empty());
  const int size = bgra.cols;
  const cv::Mat source = bgra.clone();
  // Linear light (srgb.hpp), premultiplied by alpha: texels outside the
  // head must not bring their colour in.
  cv::Mat linear(source.size(), CV_32FC4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const cv::Vec4b c = source.at<cv::Vec4b>(y, x);
      const float a = c[3] / 255.0f;
      linear.at<cv::Vec4f>(y, x) = {model::linear_from_srgb(c[0]) * a, model::linear_from_srgb(c[1]) * a,
                                    model::linear_from_srgb(c[2]) * a, a};
    }
  const auto sample = [&](glm::vec2 p) {  // bilinear, zero off the texture
    const cv::Point2f px = model_to_texture_px(p, frame, size);
    const int x0 = static_cast<int>(std::floor(px.x)), y0 = static_cast<int>(std::floor(px.y));
    const float fx = px.x - static_cast<float>(x0), fy = px.y - static_cast<float>(y0);
    cv::Vec4f sum(0, 0, 0, 0);
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const int x = x0 + dx, y = y0 + dy;
        if (x < 0 || y < 0 || x >= size || y >= size) continue;
        sum += linear.at<cv::Vec4f>(y, x) * ((dx ? fx : 1 - fx) * (dy ? fy : 1 - fy));
      }
    return sum;
  };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      cv::Vec4b& out = bgra.at<cv::Vec4b>(y, x);
      if (out[3] == 0) continue;
      const glm::vec2 p = texture_px_to_model(cv::Point2f(static_cast<float>(x), static_cast<float>(y)), frame, size);
      const glm::vec2 d = p - centre;
      const float r = std::hypot(d.x, d.y);
      const float phi = std::atan2(d.y, d.x);
      if (std::sin(phi) < model::kNeckRaySine || r < 1e-3f) continue;
      const float begin = model::between_rays(inner, phi), end = model::between_rays(outline, phi);
      if (r <= begin || end <= begin) continue;
      const float reach = std::clamp((r - begin) / (end - begin), 0.0f, 1.0f) * kWidestHalfArc;
      cv::Vec4f sum(0, 0, 0, 0);
      for (int k = -kSamplesEachSide; k <= kSamplesEachSide; ++k) {
        const float angle = phi + reach * static_cast<float>(k) / kSamplesEachSide;
        // A triangle of weights: the nearest angles count most.
        const float w = 1.0f + kSamplesEachSide - static_cast<float>(std::abs(k));
        sum += sample(centre + r * glm::vec2(std::cos(angle), std::sin(angle))) * w;
      }
      if (!(sum[3] > 0.0f)) continue;
      for (int c = 0; c < 3; ++c)
        out[c] = model::srgb_from_linear(sum[c] / sum[3]);
    }
}

}  // namespace fw::photo
