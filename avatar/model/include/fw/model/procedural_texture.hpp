#pragma once
// Textures made by code for faces that have no photo: the generic face and
// the demo avatars. They live in the generic face's texture frame, so they map
// onto the mesh exactly as a prepared photo does.
#include <functional>

#include <glm/vec3.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/model/image.hpp"

namespace fw::model {

/// Colours of a procedural face, linear-ish sRGB in [0,1].
struct Appearance {
  glm::vec3 skin{0.86f, 0.66f, 0.55f};
  glm::vec3 hair{0.23f, 0.15f, 0.09f};
  glm::vec3 iris{0.30f, 0.45f, 0.62f};
  glm::vec3 sclera{0.93f, 0.91f, 0.88f};  ///< the white of the eye, never pure white
  glm::vec3 lips{0.72f, 0.38f, 0.38f};
};

/// Skin texture: skin with soft variation, lips, brows, lashes, nostrils,
/// hair above the hairline; alpha 0 inside the eye contours (the holes the
/// eyeballs show through), 255 elsewhere.
/// @param[in] face  the generic face (texture frame)
/// @param[in] size  texture width and height in pixels, >= 16
/// @param[in] eye_holes  false for closed-lid skin: the eyes covered by lid
RgbaImage make_skin_texture(const GenericFace& face, const Appearance& look, int size = 512, bool eye_holes = true);

/// A person's own iris: its colour (sRGB, [0,1]) at `t` from the centre (0)
/// to the limbus (1) and at angle `around` (radians, counter-clockwise from
/// the viewer's right, as seen from the front).
using IrisPattern = std::function<glm::vec3(float t, float around)>;

/// Eyeball texture for EyeLayer's polar mapping: sclera, iris of a real
/// size (11.7 mm across) whatever the layer's radius, limbal ring, pupil.
/// With `iris`, the iris is that pattern (a photo's) instead of streaks of
/// `look.iris`. No highlight is painted: the renderer adds the catch-light
/// where the key light's reflection lies (avatar/render's face.frag).
RgbaImage make_eye_texture(const EyeLayer& eye, const Appearance& look, int size = 128, const IrisPattern& iris = {});

/// Mouth interior: dark cavity, a hint of upper teeth and of the tongue.
RgbaImage make_mouth_texture(int width = 128, int height = 64);

}  // namespace fw::model
