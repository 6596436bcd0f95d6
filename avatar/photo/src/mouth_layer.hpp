#pragma once
// The mouth interior of an avatar: what the photo shows between the lips
// (teeth, tongue, darkness), continued by a dark procedural cavity, laid
// over the fitted mouth cavity so that lips that part show the person's own
// mouth first.
#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// @param[in] texture    the aligned face texture (BGR)
/// @param[in] landmarks  the person's landmarks (model frame)
/// @param[in] fitted     the generic face fitted to the person
/// @return BGR image over the fitted mouth cavity's uv square
cv::Mat make_mouth_layer(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::GenericFace& fitted);

}  // namespace fw::photo
