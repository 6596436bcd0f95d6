#pragma once
// The eye parts of an avatar: alpha holes in the face texture where the
// eyes are, the iris colour, and the closed-lid layer shown for blinks.
#include <array>

#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// The eye contours (landmarks 36-41 and 42-47) as face-texture pixel polygons.
std::array<std::vector<cv::Point2f>, 2> eye_polygons_px(const ModelLandmarks& landmarks,
                                                        const model::TextureFrame& frame, int size);

/// BGRA face texture: `texture` (BGR) with alpha 0 inside the eye contours
/// and 255 outside, feathered over about a pixel so the hole's edge is soft.
cv::Mat with_eye_holes(const cv::Mat& texture, const std::array<std::vector<cv::Point2f>, 2>& eyes);

/// The iris colour (sRGB): the median of the eye-opening pixels darker than
/// the sclera, leaving out the darkest (pupil, lashes).
std::array<std::uint8_t, 3> sample_iris_colour(const cv::Mat& texture, const std::array<std::vector<cv::Point2f>, 2>& eyes);

struct ClosedLid {
  cv::Mat image;             ///< BGR crop of the face texture around both eyes, eyes filled with lid skin
  cv::Rect2f uv_rect;        ///< where it lies: (u0, v0) lower-left corner, width, height in uv, v up
};

/// Skin for closed eyes: the eye openings filled in (OpenCV inpainting, Telea)
/// from the lids around them, with lash lines along the lid margins and a
/// faint crease shadow (lash_line.hpp).
ClosedLid make_closed_lid(const cv::Mat& texture, const std::array<std::vector<cv::Point2f>, 2>& eyes);

}  // namespace fw::photo
