#pragma once
// Kernel: the lips meet and do not pass through each other. The mouth's
// opening is bounded by the inner edges of the lips; a lip pressor (AU 24)
// or tightener (AU 23) closes it, and with nothing to stop them the upper
// edge went on 1.9 mm (AU 24) to 3.6 mm (AU 23 + 24, anger) below the
// lower one. Each opposite pair of inner-edge skin nodes (upper over lower,
// TissueModel::lip_pairs) is a contact, resolved like the skull's (Lee et
// al. 1995, sec. 4.4): after the step, a pair that crossed is moved apart
// along the head's vertical, by each node's share of the inverse mass, and
// loses its closing speed; sliding along the lips stays. The pressed lips'
// tissue then has to go elsewhere, which its volume makes a bulge.
#include <glm/vec3.hpp>

namespace fw::physics {

/// Keeps `upper` at or above `lower` (y, model units) and removes the
/// speed at which they close.
/// @param[in] w_upper, w_lower  inverse masses (0: held)
/// @return true if the lips were in contact
inline bool resolve_lip_contact(float& upper_y, float& lower_y, float& upper_vy, float& lower_vy, float w_upper,
                                float w_lower) {
  const float depth = lower_y - upper_y;
  const float w = w_upper + w_lower;
  if (depth <= 0.0f || w == 0.0f) return false;
  upper_y += depth * w_upper / w;
  lower_y -= depth * w_lower / w;
  const float closing = lower_vy - upper_vy;  // > 0: still closing
  if (closing > 0.0f) {
    upper_vy += closing * w_upper / w;
    lower_vy -= closing * w_lower / w;
  }
  return true;
}

}  // namespace fw::physics
