#pragma once
// The photo's own expression, and the photo without it.
//
// A photo with a smile bakes the smile into the face texture: the avatar
// would smile through sadness. Here the action units that best explain how
// the person's landmarks differ from the generic face's are estimated, so
// that the landmarks and the texture can be taken back to a neutral face;
// the physics then adds every expression to a neutral one.
#include <array>

#include <opencv2/core.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

struct PhotoExpression {
  /// Estimated intensity of each action-unit channel (kAuChannels order);
  /// 0 for the channels not estimated.
  std::array<float, codec::kAuChannelCount> au{};
  /// The person's landmarks with that expression taken out.
  ModelLandmarks neutral{};
  /// The largest landmark move it took, model units (0: nothing to undo).
  float largest_move = 0;
};

/// How the picture of landmark `i` moves under `morph` at full intensity,
/// model units: the skin's motion less its texture's slide (see morph.hpp).
glm::vec2 picture_motion(const model::GenericFace& generic, const model::Morph& morph, std::size_t i);

/// Fits the expressive action units (brows, cheek raiser, smile, lip corner
/// depressor, lips parting, jaw drop) to the landmarks, each in [0, 1] and
/// gently pulled toward 0, while free shifts and a width of the mouth and a
/// height of each brow absorb what is the person's own shape rather than
/// an expression.
PhotoExpression estimate_expression(const model::GenericFace& generic, const ModelLandmarks& landmarks);

/// The aligned face texture taken to the neutral face: each texel at a
/// neutral position shows what the photo shows at the matching expressive
/// position (a thin-plate spline from the neutral landmarks to the photo's,
/// fixed at the texture's border).
cv::Mat neutralise_texture(const cv::Mat& texture, const model::TextureFrame& frame, const ModelLandmarks& photo,
                           const ModelLandmarks& neutral);

}  // namespace fw::photo
