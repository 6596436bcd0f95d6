#pragma once
// The lips of the face texture as they are at rest. What the photo shows
// between parted lips (teeth, tongue, the dark of the mouth) is taken out,
// so that the neutral face's lips meet lip to lip; and where they meet, the
// shadowed line that makes closed lips read as closed is drawn in the lips'
// own colour. The mouth layer keeps the photo's teeth for the speech and the
// expressions that part the lips again.
#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// The aligned face texture with the photo's mouth opening filled from the
/// lips around it (OpenCV inpainting, Telea).
/// @param[in] texture    the aligned face texture (BGR), with the photo's expression
/// @param[in] landmarks  the photo's landmarks (model frame)
/// @param[in] frame      the texture's frame
cv::Mat fill_mouth_opening(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::TextureFrame& frame);

/// Draws onto `texture` (BGR, the neutral face's) the line where closed lips
/// meet: from corner to corner between the inner lips, a pixel or so wide at
/// 84 px per model unit, no lighter than the lips' own colour in shadow and
/// fading toward the corners. Darker pixels already there (the photo's own
/// line) stay as they are.
/// @param[in] neutral  the neutral landmarks (model frame), lips closed
float lips_apart(const ModelLandmarks& landmarks);
void draw_lip_line(cv::Mat& texture, const ModelLandmarks& photo, const ModelLandmarks& neutral, const model::TextureFrame& frame);

}  // namespace fw::photo
