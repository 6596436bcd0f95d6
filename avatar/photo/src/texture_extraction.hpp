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

/// What the photo shows at each texel, with no mirror fill: where the head
/// is and is not, for cutting it from the background (a mirror-filled side
/// shows the other side's background beside the head).
struct PhotoAtTexels {
  cv::Mat seen;      ///< `size` x `size` BGR, as sampled
  /// CV_8U: 255 where the texel lies inside the photo, 0 beyond its edges
  /// (where `seen` repeats them)
  cv::Mat in_photo;
};
PhotoAtTexels photo_at_texels(const cv::Mat& photo, const Alignment& alignment, const PoseFit& fit,
                              const model::TextureFrame& frame, int size);

}  // namespace fw::photo

namespace fw::photo {

/// `texture` (extract_texture's, mirror-filled) where the mirror texel is on
/// the person, `seen` (the photo as sampled) where it is not: beside the
/// head, the other side's background is no better than this side's, and
/// the matte cuts this side's own.
/// @param matte  CV_8U over the texture frame, symmetric about its middle column
cv::Mat mirror_only_within(const cv::Mat& texture, const cv::Mat& seen, const cv::Mat& matte);

}  // namespace fw::photo
