#include "eye_layers.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>
#include <opencv2/photo.hpp>

#include "face_alignment.hpp"
#include "lash_line.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

// Rasterises the eye polygons at 4x resolution and averages down: an
// anti-aliased coverage mask (0..255) at texture resolution.
cv::Mat eye_coverage(cv::Size size, const std::array<std::vector<cv::Point2f>, 2>& eyes) {
  constexpr int kSupersample = 4;
  cv::Mat big = cv::Mat::zeros(size * kSupersample, CV_8UC1);
  for (const auto& eye : eyes) {
    std::vector<cv::Point> polygon;
    for (const cv::Point2f& p : eye)
      polygon.emplace_back(static_cast<int>((p.x + 0.5f) * kSupersample), static_cast<int>((p.y + 0.5f) * kSupersample));
    cv::fillPoly(big, std::vector<std::vector<cv::Point>>{polygon}, cv::Scalar(255), cv::LINE_AA);
  }
  cv::Mat coverage;
  cv::resize(big, coverage, size, 0, 0, cv::INTER_AREA);
  return coverage;
}

}  // namespace

std::array<std::vector<cv::Point2f>, 2> eye_polygons_px(const ModelLandmarks& landmarks,
                                                        const model::TextureFrame& frame, int size) {
  std::array<std::vector<cv::Point2f>, 2> eyes;
  const int begins[2] = {lm::kEyeRightBegin, lm::kEyeLeftBegin};
  for (std::size_t side = 0; side < 2; ++side)
    for (int i = begins[side]; i < begins[side] + 6; ++i)
      eyes[side].push_back(model_to_texture_px(landmarks[static_cast<std::size_t>(i)], frame, size));
  return eyes;
}

cv::Mat with_eye_holes(const cv::Mat& texture, const std::array<std::vector<cv::Point2f>, 2>& eyes) {
  cv::Mat alpha;
  cv::subtract(cv::Scalar(255), eye_coverage(texture.size(), eyes), alpha);
  cv::Mat bgra;
  cv::cvtColor(texture, bgra, cv::COLOR_BGR2BGRA);
  cv::insertChannel(alpha, bgra, 3);
  return bgra;
}

std::array<std::uint8_t, 3> sample_iris_colour(const cv::Mat& texture, const std::array<std::vector<cv::Point2f>, 2>& eyes) {
  const cv::Mat coverage = eye_coverage(texture.size(), eyes);
  struct Sample {
    float luminance;
    cv::Vec3b bgr;
  };
  std::vector<Sample> samples;
  for (int y = 0; y < texture.rows; ++y)
    for (int x = 0; x < texture.cols; ++x)
      if (coverage.at<std::uint8_t>(y, x) > 200) {
        const cv::Vec3b c = texture.at<cv::Vec3b>(y, x);
        samples.push_back({0.114f * c[0] + 0.587f * c[1] + 0.299f * c[2], c});
      }
  if (samples.size() < 4) return {90, 70, 50};  // a brown iris when the eyes are too small to sample
  std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.luminance < b.luminance; });
  // The iris is the darker part of the opening; its darkest tenth is pupil and lashes.
  const std::size_t begin = samples.size() / 10, end = std::max(begin + 1, samples.size() / 2);
  std::array<std::vector<std::uint8_t>, 3> channels;
  for (std::size_t i = begin; i < end; ++i)
    for (int c = 0; c < 3; ++c) channels[static_cast<std::size_t>(c)].push_back(samples[i].bgr[c]);
  std::array<std::uint8_t, 3> rgb{};
  for (int c = 0; c < 3; ++c) {
    auto& v = channels[static_cast<std::size_t>(c)];
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    rgb[static_cast<std::size_t>(2 - c)] = v[v.size() / 2];
  }
  return rgb;
}

ClosedLid make_closed_lid(const cv::Mat& texture, const std::array<std::vector<cv::Point2f>, 2>& eyes) {
  // A band around both eyes, with room above and below for the lids.
  cv::Rect2f bounds = cv::boundingRect(eyes[0]) | cv::boundingRect(eyes[1]);
  const float margin = 0.5f * bounds.height + 4.0f;
  cv::Rect crop(static_cast<int>(bounds.x - margin), static_cast<int>(bounds.y - margin),
                static_cast<int>(bounds.width + 2 * margin), static_cast<int>(bounds.height + 2 * margin));
  crop &= cv::Rect(0, 0, texture.cols, texture.rows);

  cv::Mat mask = eye_coverage(texture.size(), eyes)(crop) > 0;
  cv::dilate(mask, mask, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}));  // lashes at the rim too
  ClosedLid lid;
  cv::inpaint(texture(crop), mask, lid.image, 3.0, cv::INPAINT_TELEA);
  std::array<std::vector<cv::Point2f>, 2> eyes_in_crop = eyes;
  for (auto& eye : eyes_in_crop)
    for (cv::Point2f& p : eye) p -= cv::Point2f(static_cast<float>(crop.x), static_cast<float>(crop.y));
  draw_lash_lines(lid.image, eyes_in_crop, static_cast<float>(texture.cols) / model::generic_face().texture_frame.size);
  const float size = static_cast<float>(texture.cols);
  lid.uv_rect = {static_cast<float>(crop.x) / size, 1.0f - static_cast<float>(crop.y + crop.height) / size,
                 static_cast<float>(crop.width) / size, static_cast<float>(crop.height) / size};
  return lid;
}

}  // namespace fw::photo
