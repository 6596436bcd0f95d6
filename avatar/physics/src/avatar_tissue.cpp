#include "fw/physics/avatar_tissue.hpp"

#include <utility>

#include "fw/model/generic_face.hpp"

namespace fw::physics {
namespace {

bool same_curve(const StressStrainCurve& a, const StressStrainCurve& b) {
  return a.stiffness == b.stiffness && a.stiff_ratio == b.stiff_ratio && a.knee_strain == b.knee_strain &&
         a.residual_strain == b.residual_strain && a.compression_share == b.compression_share;
}

// What the projective matrix reads of the material: the units' curves and
// the node mass (the damping and the volume stiffness enter the weights).
bool same_material(const TissueMaterial& a, const TissueMaterial& b) {
  for (std::size_t k = 0; k < kSpringKindCount; ++k)
    if (!same_curve(a.curves[k], b.curves[k]) || a.damping[k] != b.damping[k]) return false;
  return a.volume_stiffness == b.volume_stiffness && a.volume_knee == b.volume_knee &&
         a.volume_stiff_ratio == b.volume_stiff_ratio && a.node_mass == b.node_mass && a.bone_damping == b.bone_damping;
}

}  // namespace

std::shared_ptr<const TissueModel> generic_tissue_model() {
  static const std::shared_ptr<const TissueModel> tissue =
      build_tissue_model(model::generic_face(), model::generic_face().action_units);
  return tissue;
}

bool same_topology_and_material(const TissueModel& a, const TissueModel& b) {
  return a.node_count == b.node_count && a.moving_node_count == b.moving_node_count &&
         a.inverse_mass == b.inverse_mass && a.spring_a == b.spring_a && a.spring_b == b.spring_b &&
         a.spring_kind == b.spring_kind && a.element_node == b.element_node && same_material(a.material, b.material);
}

std::shared_ptr<const TissueModel> build_avatar_tissue_model(const model::AvatarModel& avatar,
                                                             std::shared_ptr<const TissueModel> reference,
                                                             const TissueOptions& options) {
  auto built = build_tissue_model(avatar.face, avatar.morphs, options);
  if (!reference || !same_topology_and_material(*built, *reference)) return built;
  // Built once, never shared yet: its reference can still be set.
  auto own = std::const_pointer_cast<TissueModel>(std::move(built));
  own->projective_reference = reference->projective_reference ? reference->projective_reference : std::move(reference);
  return own;
}

}  // namespace fw::physics
