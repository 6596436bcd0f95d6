// The face lab's physics level of FaceSimulation: muscles driven past the
// AU table, and the tissue model swapped for one of another material. Kept
// apart from the solver's own file: neither changes how a step is taken.
#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

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
  // step. Another rest shape (the avatar's own face replacing the generic
  // one it began with) moves every node by the difference of the rests, so
  // that its displacement, what measure() projects, does not jump: a face
  // at rest stays at rest, a smile goes on smiling on the new face.
  const TissueModel& before = *model_;
  for (std::size_t i = 0; i < model->moving_node_count; ++i) {
    x_[i] += model->rest_x[i] - before.rest_x[i];
    y_[i] += model->rest_y[i] - before.rest_y[i];
    z_[i] += model->rest_z[i] - before.rest_z[i];
  }
  model_ = std::move(model);
  const TissueModel& m = *model_;
  // The bone, the held outline and the skull planes are prescribed: where
  // the new model puts them at this jaw angle (its jaw may take other
  // columns than the old one's).
  for (std::size_t v = 0; v < m.vertex_count; ++v) {
    const float share = m.jaw_share[v];
    const glm::vec3 bone = jaw_turned({m.rest_x[m.moving_node_count + v], m.rest_y[m.moving_node_count + v],
                                       m.rest_z[m.moving_node_count + v]}, share);
    x_[m.moving_node_count + v] = bone.x, y_[m.moving_node_count + v] = bone.y, z_[m.moving_node_count + v] = bone.z;
    const glm::vec3 n = m.skull_normal[v];
    const glm::vec3 turned(n.x, jaw_cos_ * n.y - jaw_sin_ * n.z, jaw_sin_ * n.y + jaw_cos_ * n.z);
    skull_normal_[v] = glm::normalize(n + share * (turned - n));
  }
  for (const std::uint16_t i : m.pinned_nodes) {
    const glm::vec3 held = jaw_turned({m.rest_x[i], m.rest_y[i], m.rest_z[i]}, m.jaw_share[i % m.vertex_count]);
    x_[i] = held.x, y_[i] = held.y, z_[i] = held.z;
  }
  lay_muscles();
  at_rest_ = false;  // other forces: let it find its rest
}

}  // namespace fw::physics
