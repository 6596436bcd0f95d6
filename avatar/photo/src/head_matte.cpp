#include "head_matte.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "face_alignment.hpp"
#include "fw/model/head_shell.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

// grabCut works on a small copy: the outline of hair needs no more, and it
// keeps the cut to a few tens of milliseconds.
constexpr int kWorkingSize = 128;
constexpr int kIterations = 4;
// The soft edge: a Gaussian over the hard cut, in texture pixels per 256.
constexpr double kFeatherSigma = 1.2;
// How far the shell may stretch or shrink a ray of the generic outline.
constexpr float kMinOutlineScale = 0.8f, kMaxOutlineScale = 1.35f;

std::vector<cv::Point> to_px(const std::vector<glm::vec2>& points, const model::TextureFrame& frame, int size) {
  std::vector<cv::Point> px;
  for (const glm::vec2& p : points) px.emplace_back(model_to_texture_px(p, frame, size));
  return px;
}

// The face: the jaw line and the brows raised a little, pulled slightly in
// toward the nose so that its edge never reaches the background.
std::vector<glm::vec2> face_polygon(const ModelLandmarks& l) {
  std::vector<glm::vec2> polygon;
  for (int i = lm::kJawBegin; i < lm::kJawEnd; ++i) polygon.push_back(l[static_cast<std::size_t>(i)]);
  for (int i = lm::kBrowLeftEnd - 1; i >= lm::kBrowRightBegin; --i)
    polygon.push_back(l[static_cast<std::size_t>(i)] + glm::vec2(0.0f, 0.15f));
  const glm::vec2 centre = l[30];
  for (glm::vec2& p : polygon) p = centre + 0.92f * (p - centre);
  return polygon;
}

std::vector<glm::vec2> ellipse(glm::vec2 centre, glm::vec2 radii) {
  std::vector<glm::vec2> points;
  for (int k = 0; k < 48; ++k) {
    const float a = 2.0f * 3.14159265f * static_cast<float>(k) / 48.0f;
    points.push_back(centre + radii * glm::vec2(std::cos(a), std::sin(a)));
  }
  return points;
}

// The seeds, in the model frame scaled by the person's face: the chin
// (landmark 8) sets how far down the head goes.
cv::Mat seed_mask(const ModelLandmarks& l, const model::TextureFrame& frame, int size) {
  cv::Mat mask(size, size, CV_8U, cv::Scalar(cv::GC_PR_BGD));
  const float chin = l[8].y;
  // Hair over the crown and the ears, the neck under the chin.
  const glm::vec2 head_centre(0.0f, 0.5f * (chin + 2.0f));
  cv::fillPoly(mask, std::vector{to_px(ellipse(head_centre, {1.45f, 0.5f * (2.0f - chin) + 0.1f}), frame, size)},
               cv::Scalar(cv::GC_PR_FGD));
  const std::vector<glm::vec2> neck = {{-0.7f, chin + 0.3f}, {0.7f, chin + 0.3f}, {0.75f, frame.origin.y},
                                       {-0.75f, frame.origin.y}};
  cv::fillPoly(mask, std::vector{to_px(neck, frame, size)}, cv::Scalar(cv::GC_PR_FGD));
  cv::fillPoly(mask, std::vector{to_px(face_polygon(l), frame, size)}, cv::Scalar(cv::GC_FGD));
  // Sure background: the top and the sides above the shoulders, far from
  // any head.
  const int band = std::max(2, size / 40);
  const int shoulders = static_cast<int>(model_to_texture_px({0.0f, chin}, frame, size).y);
  mask(cv::Rect(0, 0, size, band)).setTo(cv::GC_BGD);
  mask(cv::Rect(0, 0, band, shoulders)).setTo(cv::GC_BGD);
  mask(cv::Rect(size - band, 0, band, shoulders)).setTo(cv::GC_BGD);
  return mask;
}

// The piece of the cut that holds the face; stray blobs of background that
// happen to match the person's colours are dropped.
cv::Mat component_with(const cv::Mat& foreground, cv::Point inside) {
  cv::Mat labels;
  cv::connectedComponents(foreground, labels, 8, CV_32S);
  const int keep = labels.at<int>(inside);
  cv::Mat out = labels == keep;
  if (keep == 0) out.setTo(0);
  return out;
}

}  // namespace

cv::Mat head_matte(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::TextureFrame& frame) {
  cv::Mat small;
  cv::resize(texture, small, cv::Size(kWorkingSize, kWorkingSize), 0, 0, cv::INTER_AREA);
  cv::Mat mask = seed_mask(landmarks, frame, kWorkingSize);
  cv::Mat background_model, foreground_model;
  // grabCut seeds its colour models by k-means from OpenCV's thread-local
  // random state: fixed here, the same photo always gives the same matte,
  // whatever ran on this thread before.
  cv::RNG& random = cv::theRNG();
  const cv::RNG saved = random;
  random = cv::RNG(0x6d61747465);
  cv::grabCut(small, mask, cv::Rect(), background_model, foreground_model, kIterations, cv::GC_INIT_WITH_MASK);
  random = saved;
  cv::Mat foreground = (mask == cv::GC_FGD) | (mask == cv::GC_PR_FGD);
  foreground = component_with(foreground, model_to_texture_px(landmarks[30], frame, kWorkingSize));
  // Small gaps in the hair closed, so the shell is not pierced by them.
  cv::morphologyEx(foreground, foreground, cv::MORPH_CLOSE,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));

  cv::Mat matte;
  cv::resize(foreground, matte, texture.size(), 0, 0, cv::INTER_LINEAR);
  const double sigma = kFeatherSigma * texture.cols / 256.0;
  cv::GaussianBlur(matte, matte, cv::Size(), sigma);
  // The face itself is never cut.
  cv::fillPoly(matte, std::vector{to_px(face_polygon(landmarks), frame, texture.cols)}, cv::Scalar(255));
  return matte;
}

std::vector<float> head_outline(const cv::Mat& matte, const model::HeadShell& head, const model::TextureFrame& frame) {
  const std::size_t count = head.outline.size();
  std::vector<float> outline(count);
  const float step = frame.size / static_cast<float>(matte.cols);
  for (std::size_t k = 0; k < count; ++k) {
    const float phi = model::outline_ray_angle(k, count);
    const glm::vec2 d(std::cos(phi), std::sin(phi));
    const float generic = head.outline[k];
    // Downward rays meet the clothes and the photo's lower edge: the
    // generic neck stays.
    if (d.y < -0.6f) {
      outline[k] = generic;
      continue;
    }
    float reach = 0.0f;
    for (float r = 0.0f; r < kMaxOutlineScale * generic; r += step) {
      const cv::Point2f px = model_to_texture_px(head.centre + r * d, frame, matte.cols);
      const int x = static_cast<int>(std::lround(px.x)), y = static_cast<int>(std::lround(px.y));
      if (x < 0 || y < 0 || x >= matte.cols || y >= matte.rows || matte.at<std::uint8_t>(y, x) < 128) break;
      reach = r;
    }
    // A little beyond the matte's edge: the shell's straight edges between
    // rays then enclose the matte, whose soft alpha cuts the outline.
    outline[k] = std::clamp(reach + 0.06f, kMinOutlineScale * generic, kMaxOutlineScale * generic);
  }
  return outline;
}

}  // namespace fw::photo
