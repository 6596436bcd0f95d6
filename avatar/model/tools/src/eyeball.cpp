#include "eyeball.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace fw::facegen {
namespace {

namespace lm = model::landmarks;
using model::Mesh;

// The cornea: 11.7 mm across (an angle of about 0.51 rad on the globe),
// standing 2.5 mm proud of the globe's sphere at its apex.
constexpr float kCorneaAngle = 0.51f;
constexpr float kCorneaRise = 2.5f / model::kMillimetresPerUnit;
// A 12 mm globe is narrower than the lid opening (about 0.4 units corner to
// corner, 25 mm): a real eye's corners show the conjunctiva folding back
// and the caruncle, not the globe. Here the surface widens past 54 degrees
// from the front pole to 14.2 mm at the equator, so that the hole's corners
// show (shadowed) white; the front, where iris and lids are, is the 12 mm
// globe, and the eye turns about the globe's centre.
constexpr float kWideningFrom = 0.95f, kWideningTo = 1.55f;
constexpr float kEquatorRadius = 14.2f / model::kMillimetresPerUnit;
// The cap reaches 149 degrees from the front pole: past the silhouette when
// the eye turns up to 59 degrees, the behaviour's farthest (46 degrees
// aside, EyeHeadController::kOculomotorRangeRad, and 34 up or down at once).
constexpr float kCapAngle = 2.6f;
// The lids rest on the globe: it sits as far forward as the eye contour
// allows, this much behind it.
constexpr float kLidClearance = 0.6f / model::kMillimetresPerUnit;
// The contour's points (landmarks 36-41 or 42-47) from the first: the
// upper lid's two are the 2nd and 3rd, the lower lid's the 5th and 6th.
constexpr std::size_t kUpperLid = 1, kLowerLid = 4;

float smoothstep(float from, float to, float x) {
  const float t = std::clamp((x - from) / (to - from), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// How far in front of the centre the surface is at a distance `off_axis`
// from the eye's axis, looking straight ahead; negative when the surface
// never reaches that far out in front of its equator.
float front_at(float off_axis) {
  const float half_pi = 0.5f * std::numbers::pi_v<float>;
  if (off_axis >= eyeball_profile(half_pi)) return -1.0f;
  // The profile's distance from the axis grows monotonically up to the equator.
  float low = 0.0f, high = half_pi;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (low + high);
    (eyeball_profile(mid) * std::sin(mid) < off_axis ? low : high) = mid;
  }
  return eyeball_profile(low) * std::cos(low);
}

// The rings of the cap, as angles from the front pole: close where the
// cornea curves, wide behind the lids where little is ever seen. The iris
// and pupil are in the texture, so the mesh needs only the shape; every
// triangle costs a software renderer, sixteen eyes to a room's frame.
constexpr float kRingAngles[] = {0.17f, 0.34f, 0.51f, 0.8f, 1.1f, 1.5f, 2.0f, kCapAngle};
constexpr int kSegments = 16;

// The front cap of the eyeball, in rings around the +z pole. The uv puts the
// front pole at (0.5, 0.5) and the angle from it linearly at the uv radius.
Mesh eyeball_mesh(glm::vec3 centre) {
  constexpr int kRings = static_cast<int>(std::size(kRingAngles));
  Mesh mesh;
  mesh.positions.push_back(centre + glm::vec3(0, 0, eyeball_profile(0.0f)));
  mesh.uvs.emplace_back(0.5f, 0.5f);
  for (const float theta : kRingAngles) {
    for (int s = 0; s < kSegments; ++s) {
      const float phi = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / kSegments;
      const glm::vec3 direction(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      mesh.positions.push_back(centre + eyeball_profile(theta) * direction);
      const float r = 0.5f * theta / kCapAngle;
      mesh.uvs.emplace_back(0.5f + r * std::cos(phi), 0.5f + r * std::sin(phi));
    }
  }
  const auto at = [](int ring, int s) {
    return static_cast<std::uint32_t>(1 + (ring - 1) * kSegments + (s % kSegments));
  };
  for (int s = 0; s < kSegments; ++s) mesh.triangles.emplace_back(0u, at(1, s), at(1, s + 1));
  for (int ring = 1; ring < kRings; ++ring)
    for (int s = 0; s < kSegments; ++s) {
      mesh.triangles.emplace_back(at(ring, s), at(ring + 1, s), at(ring + 1, s + 1));
      mesh.triangles.emplace_back(at(ring, s), at(ring + 1, s + 1), at(ring, s + 1));
    }
  return mesh;
}

}  // namespace

float eyeball_profile(float angle) {
  const float cornea = std::max(0.0f, 1.0f - (angle / kCorneaAngle) * (angle / kCorneaAngle));
  return kEyeballRadius + kCorneaRise * cornea * cornea +
         (kEquatorRadius - kEyeballRadius) * smoothstep(kWideningFrom, kWideningTo, angle);
}

void build_eyes(model::GenericFace& face) {
  const int begins[2] = {lm::kEyeRightBegin, lm::kEyeLeftBegin};
  for (int side = 0; side < 2; ++side) {
    std::vector<glm::vec3> contour;
    glm::vec2 centre_xy(0.0f);
    for (int i = begins[side]; i < begins[side] + 6; ++i) {
      contour.push_back(face.skin.positions[static_cast<std::size_t>(i)]);
      centre_xy += glm::vec2(contour.back()) / 6.0f;
    }
    // The centre goes as far forward as it may with no point of the lid
    // margins (the contour's edges), nor of a chord from the upper lid to
    // the lower (where the closed lid lies), having the eyeball in front of
    // it. Not the chord from corner to corner: a real cornea stands well in
    // front of the line between the eye's corners (the closed lid curves
    // over it), and held behind that line the eyeball sat so deep that a
    // turned head's iris slid to the far side of the opening.
    float centre_z = 1e9f;
    const auto behind = [&](glm::vec3 a, glm::vec3 b) {
      for (int step = 0; step <= 8; ++step) {
        const glm::vec3 p = glm::mix(a, b, static_cast<float>(step) / 8.0f);
        const float front = front_at(glm::length(glm::vec2(p) - centre_xy));
        if (front >= 0.0f) centre_z = std::min(centre_z, p.z - kLidClearance - front);
      }
    };
    for (std::size_t i = 0; i < contour.size(); ++i) behind(contour[i], contour[(i + 1) % contour.size()]);
    for (const std::size_t upper : {kUpperLid, kUpperLid + 1})
      for (const std::size_t lower : {kLowerLid, kLowerLid + 1}) behind(contour[upper], contour[lower]);
    model::EyeLayer& eye = face.eyes[static_cast<std::size_t>(side)];
    eye.radius = kEyeballRadius;
    eye.cap_angle_rad = kCapAngle;
    eye.centre = glm::vec3(centre_xy, centre_z);
    eye.mesh = eyeball_mesh(eye.centre);
  }
}

}  // namespace fw::facegen
