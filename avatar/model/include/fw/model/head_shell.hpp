#pragma once
// Fitting the generic head shell (generic_face.hpp) to a person. Every shell
// vertex lies on a ray of the outline from the shell's centre. Along each
// ray, the part under the face's rim follows the fitted rim, and the part
// beyond it stretches to the person's silhouette on that ray (measured from
// the photo's matte and carried in the package), so the hair, ears and neck
// of the shell match the person's outline and stay joined to the face.
#include <cmath>
#include <numbers>
#include <span>

#include <glm/vec2.hpp>

#include "fw/model/generic_face.hpp"

namespace fw::model {

/// @param[in] generic    the generic face (its skin and head)
/// @param[in] fitted_xy  #V of the generic skin: where each vertex lies on this face
/// @param[in] outline    the person's silhouette radius on each of the head's
///                       rays (generic.head.outline.size() values), or empty
///                       for the generic outline moved with the face's rim
/// @return the fitted head: same topology, positions and uvs moved
HeadShell fit_head_shell(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                         std::span<const float> outline);

/// Where a ray from `centre` at angle `phi` (radians from +x, counter-
/// clockwise) first leaves `polygon`, as a distance from `centre`; 0 if it
/// does not cross it.
float ray_exit_radius(glm::vec2 centre, float phi, std::span<const glm::vec2> polygon);

/// The same for a loop in space seen from the front (the face's rim), with
/// the loop's depth where the ray leaves it, interpolated along its edge.
struct RayExit {
  float radius = 0.0f, depth = 0.0f;
};
RayExit ray_exit(glm::vec2 centre, float phi, std::span<const glm::vec3> loop);

/// The angle of ray k of an outline with `count` rays.
float outline_ray_angle(std::size_t k, std::size_t count);

/// A table with one value a ray (an outline's radii, colours along it) at
/// any angle `phi` (radians): linear between the two nearest rays.
template <typename T>
T between_rays(std::span<const T> per_ray, float phi) {
  const auto n = static_cast<float>(per_ray.size());
  const float turns = phi / (2.0f * std::numbers::pi_v<float>);
  const float at = (turns - std::floor(turns)) * n;
  const auto k = static_cast<std::size_t>(at) % per_ray.size();
  const float f = at - std::floor(at);
  return per_ray[k] * (1.0f - f) + per_ray[(k + 1) % per_ray.size()] * f;
}

/// The fitted shell always reaches at least this far (model units) beyond
/// the face's rim, so that a silhouette measured inside the rim still leaves
/// the rim something to overlap.
inline constexpr float kShellBeyondRim = 0.05f;

/// Rays pointing this far down (sine of the angle below it) run into the
/// neck and the clothes: the photo's matte says nothing useful there.
inline constexpr float kNeckRaySine = -0.6f;

/// Where on a ray the parts of the head the photo does not show (its back,
/// and what the face hides) take their colour: just inside the silhouette,
/// hair or skin; on the neck's rays, the skin just inside the jaw.
/// @param phi      the ray's angle
/// @param rim      the face rim's radius on the ray
/// @param outline  the silhouette's radius on the ray
float unseen_colour_radius(float phi, float rim, float outline);

/// For each ray of the head's outline, how far from the shell's centre
/// (model units) the hidden parts of the ray take their colour: the radius
/// that unseen_colour_radius gives for the fitted rim and `outline` (empty:
/// the generic outline moved with the face's rim), as fit_head_shell uses it.
std::vector<float> unseen_colour_radii(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                                       std::span<const float> outline);

/// The face's outer boundary loop (the longest boundary loop of the skin).
std::vector<std::uint32_t> face_rim_loop(const Mesh& skin);

}  // namespace fw::model
