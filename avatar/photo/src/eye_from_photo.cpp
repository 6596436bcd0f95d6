#include "eye_from_photo.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <opencv2/imgproc.hpp>

#include "image_conversion.hpp"
#include "iris_finder.hpp"
#include "fw/model/procedural_texture.hpp"

namespace fw::photo {
namespace {

glm::vec3 to_unit(std::array<std::uint8_t, 3> rgb) { return glm::vec3(rgb[0], rgb[1], rgb[2]) / 255.0f; }

std::array<std::uint8_t, 3> to_bytes(glm::vec3 rgb) {
  const glm::vec3 c = glm::clamp(rgb, 0.0f, 1.0f) * 255.0f + 0.5f;
  return {static_cast<std::uint8_t>(c.r), static_cast<std::uint8_t>(c.g), static_cast<std::uint8_t>(c.b)};
}

// The unwrapped ring looked up bilinearly, wrapping around the angle.
glm::vec3 sample_polar(const cv::Mat& polar, float t, float around) {
  const float row = std::clamp(t * static_cast<float>(polar.rows) - 0.5f, 0.0f, static_cast<float>(polar.rows - 1));
  const float column = (around + std::numbers::pi_v<float>) / (2.0f * std::numbers::pi_v<float>) * static_cast<float>(polar.cols) - 0.5f;
  const int r0 = static_cast<int>(row), r1 = std::min(r0 + 1, polar.rows - 1);
  const int c0 = static_cast<int>(std::floor(column));
  const float fr = row - static_cast<float>(r0), fc = column - static_cast<float>(c0);
  const auto at = [&](int r, int c) {
    const cv::Vec3f v = polar.at<cv::Vec3f>(r, ((c % polar.cols) + polar.cols) % polar.cols);
    return glm::vec3(v[0], v[1], v[2]);
  };
  return glm::mix(glm::mix(at(r0, c0), at(r0, c0 + 1), fc), glm::mix(at(r1, c0), at(r1, c0 + 1), fc), fr);
}

// The eyeball at rest looks straight out of the middle of the eye's
// landmarks, its iris the anatomical 11.7 mm: where the photo's iris sat
// higher or lower, or was larger, the white would show where the photo's
// lid covered the iris (a stare). The texture is moved and scaled so the
// iris lies behind the lids as in the photo: the eyes' mean height from
// their landmarks' middle, and the better-seen iris's size. Not sideways:
// where the eyes look left or right is the gaze's to say.
void place_iris_as_in_photo(cv::Mat& image, const model::EyeLayer& eye, float rise_units, float scale) {
  // The texture maps the angle from the front pole linearly to the radius
  // (azimuthal equidistant): cap_angle_rad at half the texture's width.
  const float rise_angle = std::asin(std::clamp(rise_units / eye.radius, -1.0f, 1.0f));
  const float px_per_rad = 0.5f * static_cast<float>(image.cols) / eye.cap_angle_rad;
  const float centre = 0.5f * static_cast<float>(image.cols);
  // Rows run down: a rise moves the iris to a smaller row.
  const cv::Matx23f to_texture(scale, 0, centre * (1 - scale), 0, scale, centre * (1 - scale) - rise_angle * px_per_rad);
  cv::Mat placed;
  cv::warpAffine(image, placed, to_texture, image.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  image = placed;
}

}  // namespace

EyeTexture make_eye_texture_from_photo(const cv::Mat& photo, const Alignment& alignment, const ModelLandmarks& landmarks,
                                       const model::EyeLayer& eye, std::array<std::uint8_t, 3> sampled_iris, int size) {
  std::optional<FoundIris> best;
  std::string why_not;
  float rise = 0;
  int found = 0;
  for (int side = 0; side < 2; ++side) {
    auto iris = find_iris(photo, alignment, landmarks, side, why_not);
    if (!iris) continue;
    rise += iris->offset.y, ++found;
    if (!best || iris->visible_fraction * iris->contrast > best->visible_fraction * best->contrast)
      best = std::move(iris);
  }
  EyeTexture result;
  model::Appearance look;
  if (!best) {
    look.iris = to_unit(sampled_iris);
    result.iris = sampled_iris;
    result.warning = why_not + "; the eyes are drawn with the iris colour sampled from the photo";
    result.image = to_bgr_mat(model::make_eye_texture(eye, look, size));
    return result;
  }
  look.iris = best->mean_rgb;
  look.sclera = best->sclera_rgb;
  const cv::Mat polar = best->polar;
  result.image = to_bgr_mat(model::make_eye_texture(eye, look, size, [&polar](float t, float around) {
    return sample_polar(polar, t, around);
  }));
  place_iris_as_in_photo(result.image, eye, rise / static_cast<float>(found), best->radius / kIrisRadiusUnits);
  result.iris = to_bytes(best->mean_rgb);
  result.from_photo = true;
  return result;
}

}  // namespace fw::photo
