#pragma once
// The person cut from the photo's background: a matte over the face texture
// whose soft edge becomes the alpha of the head and face, and the outline
// the generic head shell is stretched to.
#include <vector>

#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// The head, hair and ears down to the jaw, where the texture's colours are
/// the person's (CV_8U, the texture's size, 255 inside, soft over a few
/// pixels at the edge): OpenCV's grabCut on a downsized
/// texture, seeded from the landmarks (the face sure foreground, the head's
/// likely extent probable foreground, beyond it sure background, and the
/// shoulders beside the neck), then made one star-shaped region about the
/// middle of the face (star_shaped_region.hpp). Below the jaw nothing of the
/// photo is kept: the neck is a shape of its own, coloured like the jaw
/// (head_alpha.hpp).
/// @param[in] texture    BGR over `frame`: the photo as seen at each texel,
///                       no mirror fill (photo_at_texels)
/// @param[in] in_photo   CV_8U, the texture's size: 255 where the texel lies
///                       inside the photo (beyond it the texture repeats the
///                       photo's edge, which is never the person)
/// @param[in] landmarks  the person's landmarks, model frame
cv::Mat head_matte(const cv::Mat& texture, const cv::Mat& in_photo, const ModelLandmarks& landmarks,
                   const model::TextureFrame& frame);

/// The person's silhouette on each ray of the generic head's outline: how far
/// from the head's centre the matte reaches before its first gap, bounded
/// to what the shell can stretch to. Rays toward the shoulders keep the
/// generic neck (the matte stops at the jaw).
std::vector<float> head_outline(const cv::Mat& matte, const model::HeadShell& head, const model::TextureFrame& frame);

}  // namespace fw::photo
