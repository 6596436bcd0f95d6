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

/// How far apart the inner lips are, model units: the mean of the three
/// upper-lower pairs' heights (negative where dlib crosses closed lips).
float lip_opening(const ModelLandmarks& landmarks);

/// The aligned face texture with the photo's mouth opening filled from the
/// lips around it (OpenCV inpainting, Telea), when the lips are apart; as it
/// is when they meet (the person's own line between them stays).
/// @param[in] texture    the aligned face texture (BGR), with the photo's expression
/// @param[in] landmarks  the photo's landmarks (model frame)
/// @param[in] frame      the texture's frame
cv::Mat fill_mouth_opening(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::TextureFrame& frame);

/// Draws onto `texture` (BGR, the neutral face's, its opening filled) the
/// line where closed lips meet: from corner to corner between the inner lips, a pixel or so wide in
/// the default 320 px texture, no lighter than the lips' own colour in shadow and
/// fading toward the corners. Darker pixels already there (the photo's own
/// line) stay as they are.
/// @param[in] neutral  the neutral landmarks (model frame), lips closed
/// @param[in] photo    the photo's landmarks: nothing is drawn when its lips
///                     meet, its own line being there already
void draw_lip_line(cv::Mat& texture, const ModelLandmarks& photo, const ModelLandmarks& neutral, const model::TextureFrame& frame);

}  // namespace fw::photo
