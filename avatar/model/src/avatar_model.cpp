#include "fw/model/avatar_model.hpp"

#include "fw/model/fitted_face.hpp"
#include "fw/model/motion_cloning.hpp"

namespace fw::model {

AvatarModel make_avatar_model(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                              std::span<const float> head_outline) {
  AvatarModel avatar;
  avatar.face = fit_generic_face(generic, fitted_xy, head_outline);
  avatar.jacobians = fit_jacobians(generic.skin, fitted_xy);
  for (std::size_t c = 0; c < avatar.morphs.size(); ++c)
    avatar.morphs[c] = clone_morph(generic.action_units[c], avatar.jacobians);
  for (const Morph& component : generic.correctives)
    avatar.correctives.push_back(clone_morph(component, avatar.jacobians));
  return avatar;
}

AvatarModel generic_avatar_model() {
  AvatarModel avatar;
  avatar.face = generic_face();
  avatar.morphs = avatar.face.action_units;
  avatar.correctives = avatar.face.correctives;
  return avatar;
}

}  // namespace fw::model
