#pragma once
// The similarity that takes a photo to the model frame: eye centres to
// (-0.5, 0) and (0.5, 0), which levels the eyes and scales the face to one
// unit between the eyes (the paper's inter-iris scaling, made automatic).
#include <opencv2/core.hpp>

#include "face_finder.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::photo {

struct Alignment {
  glm::vec2 eye_midpoint_px{0.0f};
  float inter_ocular_px = 0;  ///< distance between the eye centres
  float roll_rad = 0;         ///< angle of the eye line in the photo (image y runs down), radians
  /// Photo pixel -> model frame (x right, y up).
  glm::vec2 to_model(glm::vec2 px) const;
  /// Model frame -> photo pixel.
  glm::vec2 to_photo(glm::vec2 model_point) const;
};

Alignment align_by_eyes(const PhotoLandmarks& landmarks);

/// The mean of landmarks [begin, end), e.g. an eye's centre; in whatever
/// frame the landmarks are (photo pixels or model units).
glm::vec2 landmark_centre(const PhotoLandmarks& landmarks, int begin, int end);

/// The photo at a resolution that a `size` x `size` texture over `frame`
/// can sample bilinearly without aliasing (area-averaged when the texture
/// would shrink it more than twofold), with the alignment scaled alike.
struct PhotoForSampling {
  cv::Mat photo;
  Alignment alignment;
};
PhotoForSampling photo_for_sampling(const cv::Mat& photo, const Alignment& alignment,
                                    const model::TextureFrame& frame, int size);

/// The photo resampled into the face texture by the eye alignment alone:
/// `size` x `size` pixels over `frame` (rows top down), edges extended.
cv::Mat warp_to_texture(const cv::Mat& photo, const Alignment& alignment, const model::TextureFrame& frame, int size);

/// Model-frame point -> face-texture pixel (column, row) and back.
cv::Point2f model_to_texture_px(glm::vec2 p, const model::TextureFrame& frame, int size);
glm::vec2 texture_px_to_model(cv::Point2f px, const model::TextureFrame& frame, int size);

}  // namespace fw::photo
