#pragma once
// Kernels: how strongly a muscle pulls a tissue node, by where the node is.
// Lee, Terzopoulos & Waters 1995 (sec. 5), after Waters 1987: a linear
// muscle's fibres pull toward its bony origin with a force that grows along
// the muscle toward its insertion and fades beyond it (longitudinal profile)
// and fades with the distance from the central vector (lateral profile); a
// sphincter pulls toward its centre with a force concentrated on an
// elliptical ring.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace fw::physics {

/// Where `p` lies against a muscle's axis from `origin` to `insertion`
/// (O != I): its distance along the axis from O, the axis length, and its
/// distance from the axis.
struct MusclePlace {
  float along, length, lateral;
};
inline MusclePlace place_along_muscle(const glm::vec3& p, const glm::vec3& origin, const glm::vec3& insertion) {
  const glm::vec3 axis = insertion - origin;
  const float length = glm::length(axis);
  const glm::vec3 u = axis / length;
  const glm::vec3 r = p - origin;
  const float along = glm::dot(r, u);
  return {along, length, glm::length(r - along * u)};
}

/// Weight of a linear muscle at `p`, in [0,1]:
///   t = (p - O).u / L,  longitudinal: 0 before t0, sin ramp to 1 at t = 1,
///   cos fade to 0 at t = 1 + reach / L;  lateral: cos(pi/2 d / width).
/// @param[in] p          node rest position
/// @param[in] origin     O, the bony attachment
/// @param[in] insertion  I, the tissue attachment (O != I)
/// @param[in] width      lateral radius of influence, > 0
/// @param[in] reach      how far beyond I the pull fades, > 0
/// @param[in] onset      t0 in [0,1): fraction of the muscle with no pull
inline float linear_muscle_weight(const glm::vec3& p, const glm::vec3& origin, const glm::vec3& insertion, float width,
                                  float reach, float onset) {
  constexpr float kHalfPi = 1.57079633f;
  const auto [along, length, lateral] = place_along_muscle(p, origin, insertion);
  const float t = along / length;
  if (t <= onset || lateral >= width) return 0.0f;
  float longitudinal = 1.0f;
  if (t < 1.0f) {
    longitudinal = std::sin(kHalfPi * (t - onset) / (1.0f - onset));
  } else {
    const float beyond = (along - length) / reach;
    if (beyond >= 1.0f) return 0.0f;
    longitudinal = std::cos(kHalfPi * beyond);
  }
  return longitudinal * std::cos(kHalfPi * lateral / width);
}

/// Weight of a muscle's belly at `p`, in [0,1]: how much of the muscle's
/// thickening lies under p. t = (p - O).u / L along the muscle from origin O
/// to insertion I, w = sin(pi t) cos(pi/2 d / width) between them (a belly
/// thickest half-way, thinning to its tendons), 0 elsewhere.
inline float muscle_belly_weight(const glm::vec3& p, const glm::vec3& origin, const glm::vec3& insertion, float width) {
  constexpr float kPi = 3.14159265f;
  const auto [along, length, lateral] = place_along_muscle(p, origin, insertion);
  const float t = along / length;
  if (t <= 0.0f || t >= 1.0f || lateral >= width) return 0.0f;
  return std::sin(kPi * t) * std::cos(0.5f * kPi * lateral / width);
}

/// Weight of a sphincter at `p`, in [0,1]: with the elliptical radius
///   rho = sqrt((dx/a)^2 + (dy/b)^2)  (dx, dy from the centre, in the face plane),
/// w = cos(pi/2 |rho - 1| / ring) inside the ring, 0 outside.
/// @param[in] p             node rest position
/// @param[in] centre        centre of the ellipse
/// @param[in] semi_x, semi_y  semi-axes a, b > 0
/// @param[in] ring          half-width of the ring, in units of rho, > 0
inline float sphincter_weight(const glm::vec3& p, const glm::vec3& centre, float semi_x, float semi_y, float ring) {
  constexpr float kHalfPi = 1.57079633f;
  const float dx = (p.x - centre.x) / semi_x, dy = (p.y - centre.y) / semi_y;
  const float off = std::abs(std::sqrt(dx * dx + dy * dy) - 1.0f) / ring;
  return off >= 1.0f ? 0.0f : std::cos(kHalfPi * off);
}

}  // namespace fw::physics
