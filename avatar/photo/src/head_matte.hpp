#pragma once
// The person cut from the photo's background: a matte over the face texture
// whose soft edge becomes the alpha of the head and face, and the outline
// the generic head shell is stretched to.
#include <vector>

#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// The matte of the head, hair, ears and neck (CV_8U, the texture's size, 255
/// on the person, soft over a few pixels at the edge): OpenCV's grabCut on a
/// downsized texture, seeded from the landmarks: the face sure foreground,
/// the head's likely extent (hair above, ears, neck below) probable
/// foreground, the far top and sides sure background.
/// @param[in] texture    BGR face texture over `frame`
/// @param[in] landmarks  the person's landmarks, model frame
cv::Mat head_matte(const cv::Mat& texture, const ModelLandmarks& landmarks, const model::TextureFrame& frame);

/// The person's silhouette on each ray of the generic head's outline: how far
/// from the head's centre the matte reaches before its first gap, bounded
/// to what the shell can stretch to. Rays toward the shoulders keep the
/// generic neck (the matte there is the clothes).
std::vector<float> head_outline(const cv::Mat& matte, const model::HeadShell& head, const model::TextureFrame& frame);

}  // namespace fw::photo
