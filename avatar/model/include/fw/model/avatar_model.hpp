#pragma once
// One avatar as the reconstruction needs it: the generic face fitted to the
// person and the action-unit morphs carried onto that fit. Made once per
// avatar, identically on the server and on every client.
#include <array>
#include <span>

#include <glm/vec2.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::model {

struct AvatarModel {
  GenericFace face;                                     ///< fitted
  std::array<Morph, codec::kAuChannelCount> morphs;     ///< motion-cloned onto the fit
};

/// The generic face fitted by `fitted_xy` (#V of the generic skin) and, if
/// given, the head's outline (fitted_face.hpp), with its action units cloned
/// onto the fit.
AvatarModel make_avatar_model(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                              std::span<const float> head_outline = {});

/// The generic face itself, for faces without a photo.
AvatarModel generic_avatar_model();

}  // namespace fw::model
