#pragma once
// The iris of one eye in the photo: where it is between the lids, and its
// ring unwrapped into polar form, the parts the lids hide filled in.
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <opencv2/core.hpp>

#include "face_alignment.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// The iris, 11.7 mm across, in model units (one unit: 63 mm between the eyes).
inline constexpr float kIrisRadiusUnits = 5.85f / model::kMillimetresPerUnit;

struct FoundIris {
  /// The ring unwrapped: CV_32FC3, RGB in [0,1]; row i at (i + 0.5) / rows of
  /// the way from the centre to the limbus, column j at angle
  /// 2 pi (j + 0.5) / cols - pi, counter-clockwise from the viewer's right.
  cv::Mat polar;
  glm::vec3 mean_rgb{0.0f};  ///< mean of the visible iris outside the pupil, [0,1]
  glm::vec3 sclera_rgb{0.0f};  ///< the visible white, its brightness clamped, [0,1]
  /// Where the iris's centre lies from the middle of the eye's six landmarks,
  /// model units, upright (+y up): most irises sit a little high, their top
  /// under the upper lid.
  glm::vec2 offset{0.0f};
  float radius = 0;  ///< model units: kIrisRadiusUnits within 15 %
  float visible_fraction = 0;  ///< of the iris disc, between the lids and free of glare
  float contrast = 0;          ///< white minus iris, 8-bit luminance levels
};

/// Looks for the iris of eye `side` (0 the person's right, 1 left): the
/// dark disc of the iris's size that stands out most from the rest of the
/// opening. Nothing, with `why_not` set, when the eye is too small in the
/// photo or no such disc stands out.
std::optional<FoundIris> find_iris(const cv::Mat& photo, const Alignment& alignment, const ModelLandmarks& landmarks,
                                   int side, std::string& why_not);

}  // namespace fw::photo
