#pragma once
// The prisms' bulk curve, one expression for the three solvers: linear in
// the volume lost or gained up to a knee, stiffer past it (the volumetric
// counterpart of the units' biphasic curve, stress_strain.hpp). A stiffer
// slope everywhere holds the prisms too but costs the units their travel
// (avatar/physics README, "The volume requirement"): the knee spends the
// stiffness only on the few prisms that leave the band.
#include <algorithm>
#include <cmath>

#include "fw/physics/prism_volume.hpp"

namespace fw::physics::detail {

/// The part of a volume change `lost` (rest - now) beyond `knee` x `rest`,
/// signed as `lost`; 0 inside the knee.
FW_PHYSICS_ALWAYS_INLINE float volume_beyond_knee(float lost, float rest, float knee) {
  return std::copysign(std::max(0.0f, std::abs(lost) - knee * rest), lost);
}

/// The volume the bulk term restores, in units of its first slope: `lost`
/// plus (stiff_ratio - 1) = `extra` times the part beyond the knee.
FW_PHYSICS_ALWAYS_INLINE float restoring_volume(float lost, float rest, float knee, float extra) {
  return lost + extra * volume_beyond_knee(lost, rest, knee);
}

}  // namespace fw::physics::detail
