#include "fw/model/depth_profile.hpp"

#include <algorithm>
#include <cmath>

namespace fw::model {
namespace {

// An anisotropic Gaussian bump of height `h` centred at `c` with radii `r`.
float bump(glm::vec2 p, glm::vec2 c, glm::vec2 r, float h) {
  const glm::vec2 d = (p - c) / r;
  return h * std::exp(-(d.x * d.x + d.y * d.y));
}

}  // namespace

float face_depth(glm::vec2 p) {
  // Base: a head seen from the front is close to an ellipsoid, flatter across
  // the face than around it. Its half width of 1.6 units puts the ears at the
  // silhouette.
  // A half width of 1.42 and a depth of 1.9 put the face outline at ear level
  // (landmarks 0 and 16) about 33 mm behind the outer eye corners and the
  // cheeks about 20 mm behind the nose bridge, as on an adult head.
  const float half_width = 1.42f;
  const float across = std::clamp(p.x / half_width, -0.999f, 0.999f);
  float z = 1.9f * std::sqrt(1.0f - across * across);
  // The forehead slopes back above the brows and the jaw under the chin.
  if (p.y > 0.4f) z -= 0.3f * (p.y - 0.4f) * (p.y - 0.4f);
  if (p.y < -1.5f) z -= 0.5f * (p.y + 1.5f) * (p.y + 1.5f);

  // Nose: a ridge from the bridge (low) to the tip (high), narrow at the
  // bridge and wide at the wings, ending under the tip.
  const float t = std::clamp((0.05f - p.y) / 0.62f, 0.0f, 1.0f);  // 0 at bridge top, 1 at tip
  const float ridge_height = 0.06f + 0.26f * t * t;
  const float ridge_width = 0.10f + 0.08f * t;
  float nose = ridge_height * std::exp(-(p.x * p.x) / (ridge_width * ridge_width));
  if (p.y > 0.05f) nose *= std::exp(-(p.y - 0.05f) * (p.y - 0.05f) / 0.02f);
  if (p.y < -0.6f) nose *= std::exp(-(p.y + 0.6f) * (p.y + 0.6f) / 0.012f);
  z += nose;
  z += bump(p, {-0.2f, -0.66f}, {0.1f, 0.08f}, 0.08f);  // nose wings
  z += bump(p, {+0.2f, -0.66f}, {0.1f, 0.08f}, 0.08f);

  // Eye sockets behind the lids, brow ridge above them.
  z -= bump(p, {-0.5f, 0.0f}, {0.26f, 0.16f}, 0.09f);
  z -= bump(p, {+0.5f, 0.0f}, {0.26f, 0.16f}, 0.09f);
  z += bump(p, {0.0f, 0.36f}, {0.9f, 0.12f}, 0.05f);
  // The inner corners set back beside the nose (by up to 5.7 mm). On the
  // head's curve alone the eye hole's inner corner stood 8 mm in front of
  // the cornea's apex, where a real medial canthus lies behind it; a turned
  // head's parallax then slid the iris to the far side of the opening, so
  // that a face looking at its neighbour seemed to look away. Now it stands
  // 2.6 mm in front; set back further (8 mm), dlib read the portraits'
  // avatars 12 % further from their photos.
  z -= bump(p, {-0.3f, -0.02f}, {0.12f, 0.1f}, 0.09f);
  z -= bump(p, {+0.3f, -0.02f}, {0.12f, 0.1f}, 0.09f);

  // Cheekbones, lips and chin.
  z += bump(p, {-0.72f, -0.45f}, {0.3f, 0.25f}, 0.05f);
  z += bump(p, {+0.72f, -0.45f}, {0.3f, 0.25f}, 0.05f);
  z += bump(p, {0.0f, -1.06f}, {0.38f, 0.16f}, 0.11f);  // lips, upper fuller
  z += bump(p, {0.0f, -1.2f}, {0.3f, 0.1f}, 0.04f);
  z -= bump(p, {0.0f, -1.42f}, {0.3f, 0.08f}, 0.04f);   // labiomental fold
  z += bump(p, {0.0f, -1.65f}, {0.35f, 0.18f}, 0.06f);  // chin
  return z;
}

}  // namespace fw::model
