#include "iris_finder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

// The eye is looked at in a crop of the model frame around it, upright and
// at a fixed scale whatever the photo's: 160 px per unit, the iris about
// 30 px across.
constexpr float kCropUnits = 0.6f;
constexpr int kCropSize = 96;
// An iris under 6 photo pixels across is a few blurred pixels: nothing to unwrap.
constexpr float kMinIrisRadiusPhotoPx = 3.0f;
// The iris must be this much darker than the rest of the opening (8-bit levels).
constexpr float kMinContrast = 18.0f;
// Brighter than this is glare (a lamp in the eye or in spectacle lenses).
constexpr int kGlare = 235;
constexpr int kRings = 16, kAngles = 64;

float luminance(const cv::Vec3b& bgr) { return 0.114f * bgr[0] + 0.587f * bgr[1] + 0.299f * bgr[2]; }

glm::vec3 to_rgb(const cv::Vec3f& bgr) { return glm::vec3(bgr[2], bgr[1], bgr[0]) / 255.0f; }

cv::Vec3f bilinear(const cv::Mat& bgr, cv::Point2f p) {
  const int x = std::clamp(static_cast<int>(std::floor(p.x)), 0, bgr.cols - 2);
  const int y = std::clamp(static_cast<int>(std::floor(p.y)), 0, bgr.rows - 2);
  const float fx = std::clamp(p.x - static_cast<float>(x), 0.0f, 1.0f), fy = std::clamp(p.y - static_cast<float>(y), 0.0f, 1.0f);
  const auto at = [&](int dx, int dy) { return cv::Vec3f(bgr.at<cv::Vec3b>(y + dy, x + dx)); };
  return (at(0, 0) * (1 - fx) + at(1, 0) * fx) * (1 - fy) + (at(0, 1) * (1 - fx) + at(1, 1) * fx) * fy;
}

struct Disc {
  cv::Point2f centre;
  float radius = 0;
  float mean_in = 0, mean_out = 0;
  float score() const { return mean_out - mean_in; }
};

// The dark disc of about the iris's radius `r0` that stands out most from
// the rest of the `opening` (a mask of what the lids leave visible): its
// centre may lie under a lid, most irises are partly covered.
std::optional<Disc> darkest_disc(const cv::Mat& lum, const cv::Mat& opening, const cv::Rect& eye_box, float r0) {
  double total = 0;
  int total_count = 0;
  for (int y = 0; y < lum.rows; ++y)
    for (int x = 0; x < lum.cols; ++x)
      if (opening.at<std::uint8_t>(y, x)) total += lum.at<std::uint8_t>(y, x), ++total_count;
  std::optional<Disc> best;
  for (const float scale : {0.85f, 1.0f, 1.15f}) {
    const float r = r0 * scale;
    const int reach = static_cast<int>(std::ceil(r));
    const int min_in = static_cast<int>(0.25f * std::numbers::pi_v<float> * r * r);
    for (int cy = eye_box.y - reach / 2; cy <= eye_box.y + eye_box.height + reach / 2; ++cy)
      for (int cx = eye_box.x; cx <= eye_box.x + eye_box.width; ++cx) {
        double in = 0;
        int in_count = 0;
        for (int y = std::max(0, cy - reach); y <= std::min(lum.rows - 1, cy + reach); ++y)
          for (int x = std::max(0, cx - reach); x <= std::min(lum.cols - 1, cx + reach); ++x)
            if (opening.at<std::uint8_t>(y, x) && (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r)
              in += lum.at<std::uint8_t>(y, x), ++in_count;
        if (in_count < min_in || total_count - in_count < 10) continue;
        Disc disc{cv::Point2f(static_cast<float>(cx), static_cast<float>(cy)), r, static_cast<float>(in / in_count),
                  static_cast<float>((total - in) / (total_count - in_count))};
        if (!best || disc.score() > best->score()) best = disc;
      }
  }
  return best;
}

// The white: the brighter half of the opening away from the iris, per
// channel median; its brightness held where a white is in a photo (never
// paper white, never grey as a shadow) and three quarters of its tint (skin
// blurred in at the lids, red from lenses) taken away.
glm::vec3 sclera_colour(const cv::Mat& crop, const cv::Mat& opening, const Disc& iris) {
  std::vector<cv::Vec3b> samples;
  for (int y = 0; y < crop.rows; ++y)
    for (int x = 0; x < crop.cols; ++x)
      if (opening.at<std::uint8_t>(y, x) && cv::norm(cv::Point2f(static_cast<float>(x), static_cast<float>(y)) - iris.centre) > 1.2f * iris.radius)
        samples.push_back(crop.at<cv::Vec3b>(y, x));
  glm::vec3 rgb(0.9f, 0.88f, 0.85f);
  if (samples.size() >= 6) {
    std::sort(samples.begin(), samples.end(), [](const cv::Vec3b& a, const cv::Vec3b& b) { return luminance(a) < luminance(b); });
    samples.erase(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(samples.size() / 2));
    for (int c = 0; c < 3; ++c) {
      std::vector<std::uint8_t> channel;
      for (const cv::Vec3b& s : samples) channel.push_back(s[c]);
      std::nth_element(channel.begin(), channel.begin() + static_cast<std::ptrdiff_t>(channel.size() / 2), channel.end());
      rgb[2 - c] = channel[channel.size() / 2] / 255.0f;
    }
  }
  const float y = std::max(1e-3f, glm::dot(rgb, glm::vec3(0.299f, 0.587f, 0.114f)));
  const float held = std::clamp(y, 0.62f, 0.86f);
  rgb *= held / y;
  return glm::clamp(glm::mix(glm::vec3(held), rgb, 0.25f), 0.0f, 1.0f);
}

// Fills the cells of `polar` that `valid` marks 0 from visible ones: the
// same ring mirrored top to bottom (a lid hides the top or the bottom of
// the iris, rarely both at once), then left to right, then the nearest
// visible cell around the ring, then the mean of all.
void fill_hidden(cv::Mat& polar, const cv::Mat& valid, glm::vec3 mean_rgb) {
  const cv::Mat seen = valid.clone();
  for (int ring = 0; ring < kRings; ++ring)
    for (int a = 0; a < kAngles; ++a) {
      if (seen.at<std::uint8_t>(ring, a)) continue;
      const int top_bottom = kAngles - 1 - a;
      const int left_right = ((kAngles / 2 - 1 - a) % kAngles + kAngles) % kAngles;
      int from = -1;
      if (seen.at<std::uint8_t>(ring, top_bottom)) from = top_bottom;
      else if (seen.at<std::uint8_t>(ring, left_right)) from = left_right;
      else
        for (int step = 1; step < kAngles / 2 && from < 0; ++step)
          for (const int b : {(a + step) % kAngles, (a - step + kAngles) % kAngles})
            if (from < 0 && seen.at<std::uint8_t>(ring, b)) from = b;
      polar.at<cv::Vec3f>(ring, a) =
          from >= 0 ? polar.at<cv::Vec3f>(ring, from) : cv::Vec3f(mean_rgb.r, mean_rgb.g, mean_rgb.b);
    }
}

}  // namespace

std::optional<FoundIris> find_iris(const cv::Mat& photo, const Alignment& alignment, const ModelLandmarks& landmarks,
                                   int side, std::string& why_not) {
  const float radius_photo_px = kIrisRadiusUnits * alignment.inter_ocular_px;
  if (radius_photo_px < kMinIrisRadiusPhotoPx) {
    why_not = "the eyes are too small in the photo (the iris is about " +
              std::to_string(static_cast<int>(std::lround(2 * radius_photo_px))) + " px across)";
    return std::nullopt;
  }
  const int begin = side == 0 ? lm::kEyeRightBegin : lm::kEyeLeftBegin;
  glm::vec2 centre(0.0f);
  for (int i = begin; i < begin + 6; ++i) centre += landmarks[static_cast<std::size_t>(i)] / 6.0f;
  const model::TextureFrame frame{centre - glm::vec2(0.5f * kCropUnits), kCropUnits};
  const cv::Mat crop = warp_to_texture(photo, alignment, frame, kCropSize);
  cv::Mat lum;
  cv::cvtColor(crop, lum, cv::COLOR_BGR2GRAY);

  // What the lids leave visible, a little inside the contour (lashes), free of glare.
  std::vector<cv::Point> polygon;
  for (int i = begin; i < begin + 6; ++i) {
    const cv::Point2f p = model_to_texture_px(landmarks[static_cast<std::size_t>(i)], frame, kCropSize);
    polygon.emplace_back(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
  }
  cv::Mat opening = cv::Mat::zeros(crop.size(), CV_8UC1);
  cv::fillPoly(opening, std::vector<std::vector<cv::Point>>{polygon}, cv::Scalar(255));
  cv::erode(opening, opening, cv::getStructuringElement(cv::MORPH_ELLIPSE, {3, 3}), {-1, -1}, 2);
  opening &= lum < kGlare;

  const float r0 = kIrisRadiusUnits * static_cast<float>(kCropSize) / kCropUnits;
  const auto disc = darkest_disc(lum, opening, cv::boundingRect(polygon), r0);
  if (!disc || disc->score() < kMinContrast) {
    why_not = "no iris stands out in the eye opening";
    return std::nullopt;
  }

  FoundIris iris;
  iris.offset = texture_px_to_model(disc->centre, frame, kCropSize) - centre;
  iris.radius = disc->radius * kCropUnits / static_cast<float>(kCropSize);
  iris.sclera_rgb = sclera_colour(crop, opening, *disc);
  iris.contrast = disc->score();
  // Iris pixels brighter than halfway to the white are a catchlight or a
  // reflection in spectacles, not the iris.
  const float sclera_level = 255.0f * glm::dot(iris.sclera_rgb, glm::vec3(0.299f, 0.587f, 0.114f));
  const float too_bright = disc->mean_in + 0.5f * std::max(0.0f, sclera_level - disc->mean_in);
  iris.polar = cv::Mat(kRings, kAngles, CV_32FC3);
  cv::Mat valid = cv::Mat::zeros(kRings, kAngles, CV_8UC1);
  glm::vec3 sum(0.0f);
  int counted = 0;
  for (int ring = 0; ring < kRings; ++ring)
    for (int a = 0; a < kAngles; ++a) {
      const float t = (static_cast<float>(ring) + 0.5f) / kRings;
      const float around = 2.0f * std::numbers::pi_v<float> * (static_cast<float>(a) + 0.5f) / kAngles - std::numbers::pi_v<float>;
      const cv::Point2f p = disc->centre + t * disc->radius * cv::Point2f(std::cos(around), -std::sin(around));
      const int x = static_cast<int>(std::lround(p.x)), y = static_cast<int>(std::lround(p.y));
      const cv::Vec3f bgr = bilinear(crop, p);
      iris.polar.at<cv::Vec3f>(ring, a) = cv::Vec3f(bgr[2], bgr[1], bgr[0]) / 255.0f;
      if (x < 0 || y < 0 || x >= crop.cols || y >= crop.rows || !opening.at<std::uint8_t>(y, x) ||
          lum.at<std::uint8_t>(y, x) > too_bright)
        continue;
      valid.at<std::uint8_t>(ring, a) = 1;
      if (t >= 0.4f) sum += to_rgb(bgr), ++counted;  // outside the pupil
    }
  iris.visible_fraction = static_cast<float>(cv::countNonZero(valid)) / (kRings * kAngles);
  if (counted == 0) {
    why_not = "the iris is hidden by the lids or by glare";
    return std::nullopt;
  }
  iris.mean_rgb = sum / static_cast<float>(counted);
  fill_hidden(iris.polar, valid, iris.mean_rgb);
  return iris;
}

}  // namespace fw::photo
