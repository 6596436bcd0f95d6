// The face lab's physics level of FaceSimulation: muscles driven past the
// AU table, and the tissue model swapped for one of another material. Kept
// apart from the solver's own file: neither changes how a step is taken.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "fw/physics/face_simulation.hpp"

namespace fw::physics {

void FaceSimulation::set_muscle_floor(const std::array<float, kMuscleCount>& floor) {
  for (std::size_t i = 0; i < kMuscleCount; ++i)
    floor_[i] = std::isfinite(floor[i]) ? std::clamp(floor[i], 0.0f, 1.0f) : 0.0f;
  set_action_units(au_targets_);  // the targets again, with the new floor
}

void FaceSimulation::replace_model(std::shared_ptr<const TissueModel> model) {
  assert(model && model->node_count == model_->node_count);
  if (!model || model->node_count != model_->node_count) return;
  // The material changes the units' curves and damping, the volume
  // stiffness and the stable sub-step, all read from the model at every
  // step; the muscles are laid on the same face, so their strengths (with
  // this face's own variation) stay.
  model_ = std::move(model);
  at_rest_ = false;  // the same shape, other forces: let it find its rest
}

}  // namespace fw::physics
