#include "head_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "face_alignment.hpp"
#include "fw/model/head_shell.hpp"

namespace fw::photo {
namespace {

// How far (model units) beyond the outline the alpha stays solid: the
// silhouette's texels, whatever the filter and the soft edge, are inside.
constexpr float kBeyondOutline = 0.1f;
// The soft edge, in texture pixels per 256 (as the matte's).
constexpr double kEdgeSigma = 1.2;

}  // namespace

cv::Mat head_alpha(const cv::Mat& person, std::span<const float> outline, std::span<const glm::vec2> fitted_rim,
                   const model::HeadShell& head, const model::TextureFrame& frame) {
  const int size = person.cols;
  constexpr int kShift = 4;
  const float unit = static_cast<float>(1 << kShift);
  std::vector<cv::Point> silhouette;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const float phi = model::outline_ray_angle(k, outline.size());
    const glm::vec2 d(std::cos(phi), std::sin(phi));
    // The neck's rays too: cut at the outline, the neck's side showed a
    // ragged dark scribble on a head turned 60 degrees (the shell samples
    // its texels there, and mipmaps mixed in the alpha beyond them).
    const float beyond = kBeyondOutline;
    // The shell never ends inside the face's rim (fit_head_shell).
    const float past_rim = model::ray_exit_radius(head.centre, phi, fitted_rim) + model::kShellBeyondRim;
    const float reach = std::max(outline[k], past_rim);
    const cv::Point2f px = model_to_texture_px(head.centre + (reach + beyond) * d, frame, size);
    silhouette.emplace_back(static_cast<int>(std::lround(px.x * unit)), static_cast<int>(std::lround(px.y * unit)));
  }
  cv::Mat shell(person.size(), CV_8U, cv::Scalar(0));
  cv::fillPoly(shell, std::vector{silhouette}, cv::Scalar(255), cv::LINE_8, kShift);
  cv::GaussianBlur(shell, shell, cv::Size(), kEdgeSigma * size / 256.0);
  return cv::max(person, shell);
}

}  // namespace fw::photo
