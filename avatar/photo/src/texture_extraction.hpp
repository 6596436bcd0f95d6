#pragma once
// The face texture taken from the photo through the head's pose.
//
// Each texel of the texture frame is a point on the person's face surface
// (frontal position, depth from the fitted relief); the pose projects it
// into the photo, where it is sampled. A texel the photo cannot show well
// (turned away, or hidden behind the nose) is filled from its mirror image
// on the other side of the face, weighted smoothly, so there is no seam.
#include <opencv2/core.hpp>

#include "face_alignment.hpp"
#include "head_pose_fit.hpp"

namespace fw::photo {

/// @param photo      the upright photo (BGR)
/// @param alignment  the eye alignment the pose was fitted in
/// @param fit        the head's pose and frontal frame
/// @return `size` x `size` BGR over the texture frame (rows top down)
cv::Mat extract_texture(const cv::Mat& photo, const Alignment& alignment, const PoseFit& fit,
                        const model::TextureFrame& frame, int size);

}  // namespace fw::photo
