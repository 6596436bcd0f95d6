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
// The neck: solid to this far below the chin, gone at the second (model
// units, inter-ocular distances; a neck shows about its own width below the
// chin in a head-and-shoulders portrait before the collar).
constexpr float kNeckSolid = 0.3f, kNeckGone = 0.9f;
// The soft edge, in texture pixels per 256 (as the matte's).
constexpr double kEdgeSigma = 1.2;

}  // namespace

cv::Mat head_alpha(const cv::Mat& person, std::span<const float> outline, std::span<const glm::vec2> fitted_rim,
                   const model::HeadShell& head, const ModelLandmarks& landmarks, const model::TextureFrame& frame) {
  const int size = person.cols;
  constexpr int kShift = 4;
  const float unit = static_cast<float>(1 << kShift);
  std::vector<cv::Point> silhouette;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const float phi = model::outline_ray_angle(k, outline.size());
    const glm::vec2 d(std::cos(phi), std::sin(phi));
    const float beyond = d.y < model::kNeckRaySine ? 0.0f : kBeyondOutline;
    // The shell never ends inside the face's rim (fit_head_shell).
    const float reach = std::max(outline[k], model::ray_exit_radius(head.centre, phi, fitted_rim) + model::kShellBeyondRim);
    const cv::Point2f px = model_to_texture_px(head.centre + (reach + beyond) * d, frame, size);
    silhouette.emplace_back(static_cast<int>(std::lround(px.x * unit)), static_cast<int>(std::lround(px.y * unit)));
  }
  cv::Mat shell(person.size(), CV_8U, cv::Scalar(0));
  cv::fillPoly(shell, std::vector{silhouette}, cv::Scalar(255), cv::LINE_8, kShift);
  // The neck's end: whatever the shell shows below the chin fades out.
  const float chin = landmarks[model::landmarks::kChin].y;
  const float solid_to = chin - kNeckSolid, gone_at = chin - kNeckGone;
  for (int row = 0; row < size; ++row) {
    const float y = texture_px_to_model(cv::Point2f(0.0f, static_cast<float>(row)), frame, size).y;
    shell.row(row) *= std::clamp((y - gone_at) / (solid_to - gone_at), 0.0f, 1.0f);
  }
  cv::GaussianBlur(shell, shell, cv::Size(), kEdgeSigma * size / 256.0);
  return cv::max(person, shell);
}

}  // namespace fw::photo
