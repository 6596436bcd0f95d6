#pragma once
// Every avatar's own tissue model: the lattice built on its fitted face
// (its package's fit) and measured against its cloned action-unit morphs,
// the morphs its viewers draw it with. The fit moves the generic face's
// vertices and keeps its mesh, so the lattice keeps the generic one's
// topology: the same nodes, units, prisms and muscles, at the fitted face's
// rest lengths, rest volumes, skull planes and muscle geometry.
//
// Projective dynamics factors its global matrix once per topology, masses,
// weights and step length (Bouaziz et al. 2014, sec. 4), none of which the
// rest shape enters except the prisms' weights (kappa s |grad V|^2 at rest):
// a fitted model takes the generic model's weights and factorisations
// (TissueModel::projective_reference) and keeps its own rest shape in the
// local step, so a room's faces of many avatars share one factorisation
// and one batched solve. Its rest shape is still the exact equilibrium;
// under load each prism's volume stiffness is the generic face's prism's
// (README, "Every avatar its own face", says how far that moves the skin).
#include <memory>

#include "fw/model/avatar_model.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::physics {

/// The generic face's tissue model (normal skin), built once per process
/// and shared: the reference every fitted face's model solves with.
std::shared_ptr<const TissueModel> generic_tissue_model();

/// The tissue model of `avatar`'s fitted face with `options`' material.
/// When `reference` has the same topology and material, the new model
/// shares its projective-dynamics factorisations (projective_reference);
/// otherwise (another material: the face lab's skin sliders) it factors
/// its own. About 7 ms and 0.6 MB on the generic face's 228 vertices.
std::shared_ptr<const TissueModel> build_avatar_tissue_model(const model::AvatarModel& avatar,
                                                             std::shared_ptr<const TissueModel> reference,
                                                             const TissueOptions& options = {});

/// Whether `a` and `b` have the same nodes, held nodes, units, prisms and
/// material: what one projective factorisation needs them to share.
bool same_topology_and_material(const TissueModel& a, const TissueModel& b);

}  // namespace fw::physics
