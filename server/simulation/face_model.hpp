#pragma once
// One avatar's face as its room simulates it: the fit and cloned action
// units its package makes (what every client draws it with), and the
// tissue model built on that fit (avatar/physics avatar_tissue.hpp) with
// the corrective components cloned onto it.
// Shared, read-only, by every room the avatar is in (face_models.hpp).
// Private to this module: rooms hold it only by pointer.
#include <memory>

#include "fw/model/avatar_model.hpp"
#include "fw/physics/corrective_projection.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::server {

struct FaceModel {
  model::AvatarModel avatar;
  std::shared_ptr<const physics::TissueModel> tissue;
  std::shared_ptr<const physics::CorrectiveBasis> correctives;
};

}  // namespace fw::server
