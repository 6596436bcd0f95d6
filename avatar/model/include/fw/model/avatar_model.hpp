#pragma once
// One avatar as the reconstruction needs it: the generic face fitted to the
// person and the action-unit morphs carried onto that fit. Made once per
// avatar, identically on the server and on every client.
#include <array>
#include <span>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::model {

struct AvatarModel {
  GenericFace face;                                     ///< fitted
  std::array<Morph, codec::kAuChannelCount> morphs;     ///< motion-cloned onto the fit
  /// The generic face's corrective components (GenericFace::correctives),
  /// motion-cloned onto the fit like the action units.
  std::vector<Morph> correctives;
  /// The fit's local linear maps (motion_cloning.hpp), #V; empty for the
  /// generic face itself (identity). Kept so that a unit its person
  /// redefines (unit_morphs.hpp) is carried onto the fit as the shipped ones were.
  std::vector<glm::mat2> jacobians;
};

/// The generic face fitted by `fitted_xy` (#V of the generic skin) and, if
/// given, the head's outline (fitted_face.hpp), with its action units cloned
/// onto the fit, and its corrective components likewise.
AvatarModel make_avatar_model(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                              std::span<const float> head_outline = {});

/// The generic face itself, for faces without a photo.
AvatarModel generic_avatar_model();

}  // namespace fw::model
