#include "head_matte.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "face_alignment.hpp"
#include "star_shaped_region.hpp"
#include "fw/model/head_shell.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

// grabCut works on a small copy: the outline of hair needs no more, and it
// keeps the cut to a few tens of milliseconds.
constexpr int kWorkingSize = 128;
constexpr int kIterations = 4;
// Sure background starts this far (model units, inter-ocular distances)
// beyond the likely head: hair stands out from a head by less.
constexpr float kSureBackgroundBeyond = 0.6f;
// The jaw's lower part (landmarks 3..13): below it lies the neck.
constexpr int kLowerJawBegin = 3, kLowerJawLast = 13;
constexpr float kBelowJawMargin = 0.06f;
// Saturation and value (of 255) from which a cold hue is not the person's:
// a third saturated, and bright enough for its hue to mean something.
constexpr int kMinSaturation = 85, kMinValue = 60;
// Slivers narrower than this many working pixels (0.3 units) are dropped.
constexpr int kOpening = 7;
// The star-shaped outline: rays 2 degrees apart, a gap of up to 2 working
// pixels bridged, the median of 9 rays (a spike narrower than 8 degrees
// goes), drawn back 2.5 working pixels (0.1 units) inside: the downsized
// copy mixes hair and background in the pixels along the edge, and grabCut
// takes a pixel or two of a dark background beside dark hair.
constexpr int kRays = 180, kMedianHalfWindow = 4;
constexpr float kMaxGap = 2.0f, kInset = 2.5f;
// A working pixel at least this much inside the photo counts as in it.
constexpr int kInPhoto = 250;
const cv::Scalar kBeyondPhotoColour(255, 0, 255);
// The soft edge: a Gaussian over the hard cut, in texture pixels per 256.
constexpr double kFeatherSigma = 1.2;
// How far the shell may stretch or shrink a ray of the generic outline. It
// may shrink to the matte (to half the generic reach; the shell never ends
// inside the face's rim anyway): a shell held wider than the matte shows a
// band of filled colour beside the face that widens it (Grace Hopper's
// grey hair is cut with the background: at 0.8, her avatar's landmarks
// drifted from 0.031 to 0.050 inter-ocular in the Likeness test).
constexpr float kMinOutlineScale = 0.5f, kMaxOutlineScale = 1.35f;

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

// The head's likely extent: hair over the crown and the ears.
struct HeadEllipse {
  glm::vec2 centre, radii;
};
HeadEllipse likely_head(const ModelLandmarks& l) {
  const float chin = l[lm::kChin].y;
  return {{0.0f, 0.5f * (chin + 2.0f)}, {1.45f, 0.5f * (2.0f - chin) + 0.1f}};
}

// Below the jaw line, between the ends of the jaw's lower part: the neck and
// whatever the person wears. The photo's colours there are not trusted (a
// collar, a shirt, the shoulders match skin or hair as often as not); the
// neck gets the jaw's skin instead (head_alpha.hpp).
std::vector<glm::vec2> below_jaw(const ModelLandmarks& l, const model::TextureFrame& frame) {
  std::vector<glm::vec2> polygon;
  for (int i = kLowerJawBegin; i <= kLowerJawLast; ++i)
    polygon.push_back(l[static_cast<std::size_t>(i)] - glm::vec2(0.0f, kBelowJawMargin));
  polygon.emplace_back(l[kLowerJawLast].x, frame.origin.y - 1.0f);
  polygon.emplace_back(l[kLowerJawBegin].x, frame.origin.y - 1.0f);
  return polygon;
}

// The seeds, in the model frame scaled by the person's face: the chin
// (landmark 8) sets how far down the head goes.
cv::Mat seed_mask(const ModelLandmarks& l, const model::TextureFrame& frame, int size) {
  cv::Mat mask(size, size, CV_8U, cv::Scalar(cv::GC_BGD));
  const HeadEllipse head = likely_head(l);
  // Sure background beyond a generous ellipse round the head: grabCut's
  // background colours then include whatever stands beside the head (a
  // flag, a wall, a window), not only the far corners.
  const glm::vec2 beyond_radii = head.radii + glm::vec2(kSureBackgroundBeyond);
  cv::fillPoly(mask, std::vector{to_px(ellipse(head.centre, beyond_radii), frame, size)}, cv::Scalar(cv::GC_PR_BGD));
  // The shoulders: beside the neck, below the jaw.
  const float chin = l[lm::kChin].y;
  const float neck_half_width = 0.5f * (l[kLowerJawLast].x - l[kLowerJawBegin].x) + 0.15f;
  const cv::Point2f shoulder_top = model_to_texture_px({neck_half_width, chin + 0.3f}, frame, size);
  const int centre_x = static_cast<int>(model_to_texture_px({0.0f, 0.0f}, frame, size).x);
  const int half = std::max(0, static_cast<int>(shoulder_top.x) - centre_x);
  const int top = std::clamp(static_cast<int>(shoulder_top.y), 0, size);
  mask(cv::Rect(0, top, std::max(0, centre_x - half), size - top)).setTo(cv::GC_BGD);
  mask(cv::Rect(std::min(size, centre_x + half), top, size - std::min(size, centre_x + half), size - top))
      .setTo(cv::GC_BGD);
  cv::fillPoly(mask, std::vector{to_px(ellipse(head.centre, head.radii), frame, size)}, cv::Scalar(cv::GC_PR_FGD));
  cv::fillPoly(mask, std::vector{to_px(below_jaw(l, frame), frame, size)}, cv::Scalar(cv::GC_PR_BGD));
  cv::fillPoly(mask, std::vector{to_px(face_polygon(l), frame, size)}, cv::Scalar(cv::GC_FGD));
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

// Clearly saturated greens, blues and violets (OpenCV hue 38..142 of 180:
// 76 to 284 degrees). Skin and natural hair lie between red and yellow (hue
// 0 to about 30 degrees), or are grey; dyed hair or a hat in these colours
// is cut too, the price of never keeping a blue sky or a flag.
cv::Mat cold_saturated(const cv::Mat& bgr) {
  cv::Mat hsv;
  cv::cvtColor(bgr, hsv, cv::COLOR_BGR2HSV);
  cv::Mat cold;
  cv::inRange(hsv, cv::Scalar(38, kMinSaturation, kMinValue), cv::Scalar(142, 255, 255), cold);
  return cold;
}

}  // namespace

cv::Mat head_matte(const cv::Mat& texture, const cv::Mat& in_photo, const ModelLandmarks& landmarks,
                   const model::TextureFrame& frame) {
  cv::Mat small, small_in_photo;
  cv::resize(texture, small, cv::Size(kWorkingSize, kWorkingSize), 0, 0, cv::INTER_AREA);
  cv::resize(in_photo, small_in_photo, small.size(), 0, 0, cv::INTER_AREA);
  const cv::Mat beyond_photo = small_in_photo < kInPhoto;
  cv::Mat mask = seed_mask(landmarks, frame, kWorkingSize);
  // Beyond the photo's edge: background, in a colour of its own, so that the
  // edge's pixels repeated there (hair, often) do not teach grabCut that
  // hair is background.
  mask.setTo(cv::GC_BGD, beyond_photo);
  small.setTo(kBeyondPhotoColour, beyond_photo);
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
  foreground.setTo(0, beyond_photo);
  cv::fillPoly(foreground, std::vector{to_px(below_jaw(landmarks, frame), frame, kWorkingSize)}, cv::Scalar(0));
  // Colours no skin or hair has: a flag's blue beside a dark cap, a green
  // wall beside dark hair, which grabCut's mixtures may still take in.
  foreground.setTo(0, cold_saturated(small) & (mask != cv::GC_FGD));
  // Thin slivers beside the head go (a strip of flag the colour of a cap, of
  // wall the colour of hair): the head's parts are wider.
  cv::morphologyEx(foreground, foreground, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(kOpening, kOpening)));
  cv::fillPoly(foreground, std::vector{to_px(face_polygon(landmarks), frame, kWorkingSize)}, cv::Scalar(255));
  const glm::vec2 centre_model(0.0f, 0.5f * landmarks[lm::kNoseTip].y);
  const cv::Point2f centre = model_to_texture_px(centre_model, frame, kWorkingSize);
  foreground = fill_holes(component_with(foreground, centre));
  // The head as one star-shaped region about the middle of the face: no
  // holes, no scraps; drawn again at full size, a little inside the cut so
  // that the soft edge's solid part holds no background.
  std::vector<float> reach = median_across_rays(ray_reach(foreground, centre, kRays, kMaxGap), kMedianHalfWindow);
  for (float& r : reach) r = std::max(0.0f, r - kInset);
  const float scale = static_cast<float>(texture.cols) / kWorkingSize;
  cv::Mat matte = fill_reach(reach, centre, texture.size(), scale);
  matte.setTo(0, in_photo < kInPhoto);
  // The same colours at full size, where the downsized copy had mixed a
  // flag's blue with the dark cap beside it: those texels take the
  // person's colours from further in (fill_beyond_matte).
  matte.setTo(0, cold_saturated(texture));
  // The face itself is never cut.
  const std::vector face{to_px(face_polygon(landmarks), frame, texture.cols)};
  cv::fillPoly(matte, face, cv::Scalar(255));
  cv::GaussianBlur(matte, matte, cv::Size(), kFeatherSigma * texture.cols / 256.0);
  cv::fillPoly(matte, face, cv::Scalar(255));
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
    if (d.y < model::kNeckRaySine) {
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
    // The shell's silhouette is the outline: the alpha is solid a little
    // beyond it (head_alpha.hpp), its colours there those of the person's
    // edge, so a head turned aside shows no cut-out side.
    outline[k] = std::clamp(reach, kMinOutlineScale * generic, kMaxOutlineScale * generic);
  }
  return outline;
}

}  // namespace fw::photo
