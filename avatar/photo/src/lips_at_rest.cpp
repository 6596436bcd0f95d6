#include "lips_at_rest.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "face_alignment.hpp"
#include "polyline_distance.hpp"

namespace fw::photo {
namespace lm = model::landmarks;

float lip_opening(const ModelLandmarks& landmarks) {
  float gap = 0;
  for (const auto& [upper, lower] : {std::pair{61, 67}, {62, 66}, {63, 65}})
    gap += (landmarks[static_cast<std::size_t>(upper)].y - landmarks[static_cast<std::size_t>(lower)].y) / 3.0f;
  return gap;
}

namespace {

std::vector<cv::Point2f> texture_points(const ModelLandmarks& landmarks, std::initializer_list<int> indices,
                                        const model::TextureFrame& frame, int size) {
  std::vector<cv::Point2f> points;
  for (const int i : indices) points.push_back(model_to_texture_px(landmarks[static_cast<std::size_t>(i)], frame, size));
  return points;
}

std::vector<cv::Point> rounded(const std::vector<cv::Point2f>& points) {
  std::vector<cv::Point> out;
  for (const cv::Point2f& p : points) out.emplace_back(cvRound(p.x), cvRound(p.y));
  return out;
}

// How dark the line between closed lips is: the lips' median colour scaled
// by this. A little under half their brightness reads as the shadow where
// lips meet: lighter, the lips look smeared together and dlib reads them
// apart (Jesper's lip gap 0.076 of the mouth's width at 0.7, 0.060 at 0.55,
// 0.051 at 0.45, his avatar with the head's outline); much darker, the
// line reads as a gap.
constexpr float kLineShade = 0.45f;

// Lips further apart than this (model units) show teeth or the mouth's
// dark between them. dlib's points on closed lips lie within about 0.015
// (a pixel or two at 80 px between the eyes): twice that is apart.
constexpr float kApart = 0.03f;

// Half the line's width, model units (0.4 mm; a third of a pixel in the
// default 320 px texture, with a pixel's soft edge either side).
constexpr float kLineHalfWidth = 0.006f;

bool lips_apart(const ModelLandmarks& landmarks) { return lip_opening(landmarks) > kApart; }

// The lips' median colour, within the outer lip's outline (closed at rest:
// no opening inside it).
cv::Vec3f median_lip_colour(const cv::Mat& texture, const ModelLandmarks& neutral, const model::TextureFrame& frame) {
  cv::Mat ring = cv::Mat::zeros(texture.size(), CV_8U);
  cv::fillPoly(ring, std::vector<std::vector<cv::Point>>{rounded(texture_points(
                         neutral, {48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59}, frame, texture.cols))},
               cv::Scalar(255));
  std::array<std::vector<std::uint8_t>, 3> channels;
  for (int y = 0; y < texture.rows; ++y)
    for (int x = 0; x < texture.cols; ++x)
      if (ring.at<std::uint8_t>(y, x))
        for (int c = 0; c < 3; ++c) channels[static_cast<std::size_t>(c)].push_back(texture.at<cv::Vec3b>(y, x)[c]);
  cv::Vec3f median(0, 0, 0);
  for (int c = 0; c < 3; ++c) {
    auto& v = channels[static_cast<std::size_t>(c)];
    if (v.empty()) return median;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    median[c] = v[v.size() / 2];
  }
  return median;
}

}  // namespace

cv::Mat fill_mouth_opening(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::TextureFrame& frame) {
  if (!lips_apart(landmarks)) return texture.clone();
  cv::Mat mask = cv::Mat::zeros(texture.size(), CV_8U);
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{rounded(
                         texture_points(landmarks, {60, 61, 62, 63, 64, 65, 66, 67}, frame, texture.cols))},
               cv::Scalar(255));
  // dlib's inner lip points sit a pixel or so either side of the lips' edge:
  // the teeth reach that far past them.
  cv::dilate(mask, mask, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));
  cv::Mat filled;
  cv::inpaint(texture, mask, filled, 3.0, cv::INPAINT_TELEA);
  return filled;
}

void draw_lip_line(cv::Mat& texture, const ModelLandmarks& photo, const ModelLandmarks& neutral, const model::TextureFrame& frame) {
  if (!lips_apart(photo)) return;
  const int size = texture.cols;
  std::vector<cv::Point2f> line = texture_points(neutral, {lm::kMouthCornerRight, 60}, frame, size);
  for (const auto& [upper, lower] : {std::pair{61, 67}, {62, 66}, {63, 65}})
    line.push_back(model_to_texture_px(0.5f * (neutral[static_cast<std::size_t>(upper)] +
                                               neutral[static_cast<std::size_t>(lower)]),
                                       frame, size));
  for (const cv::Point2f& p : texture_points(neutral, {64, lm::kMouthCornerLeft}, frame, size)) line.push_back(p);
  const cv::Vec3f shade = median_lip_colour(texture, neutral, frame) * kLineShade;
  const float half_width = kLineHalfWidth * static_cast<float>(size) / frame.size;
  cv::Rect area = cv::boundingRect(line);
  area.x -= 3, area.y -= 3, area.width += 6, area.height += 6;
  area &= cv::Rect(0, 0, texture.cols, texture.rows);
  for (int y = area.y; y < area.y + area.height; ++y)
    for (int x = area.x; x < area.x + area.width; ++x) {
      const NearestOnPolyline nearest = nearest_on(line, {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f});
      // Strong over the middle of the mouth, fading out over the last
      // fifth toward each corner, where the lips thin into the cheek.
      const float toward_corner = std::min(nearest.along, 1.0f - nearest.along) / 0.2f;
      const float amount = line_cover(nearest.distance, half_width) * std::clamp(toward_corner, 0.0f, 1.0f);
      cv::Vec3b& px = texture.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c)
        px[c] = cv::saturate_cast<std::uint8_t>(px[c] + amount * std::min(0.0f, shade[c] - px[c]));
    }
}

}  // namespace fw::photo
