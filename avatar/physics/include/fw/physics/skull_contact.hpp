#pragma once
// Kernel: the skull as an impenetrable surface the tissue slides over. Lee,
// Terzopoulos & Waters 1995 (sec. 4.4) give each node a skull point and
// normal under it and cancel any motion into the bone; the tangential motion
// stays, so the skin slides. Locally the skull is the plane through the
// node's bone point with the bone normal.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace fw::physics {

/// Moves a node that went below `min_height` above the skull plane back
/// onto it and removes the part of its velocity that points into the bone.
/// @param[in]     bone        the skull point under the node
/// @param[in]     normal      unit skull normal, pointing out of the bone
/// @param[in]     min_height  how far above the plane the node must stay, >= 0
/// @param[in,out] position    node position
/// @param[in,out] velocity    node velocity
/// @return true if the node was in contact
inline bool resolve_skull_contact(const glm::vec3& bone, const glm::vec3& normal, float min_height, glm::vec3& position,
                                  glm::vec3& velocity) {
  const float depth = min_height - glm::dot(position - bone, normal);
  if (depth <= 0.0f) return false;
  position += depth * normal;
  const float inward = glm::dot(velocity, normal);
  if (inward < 0.0f) velocity -= inward * normal;
  return true;
}

}  // namespace fw::physics
