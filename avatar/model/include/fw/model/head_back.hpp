#pragma once
// The colours of the head the photo never shows: its back, and its sides
// behind the silhouette. They come from a small disc painted into a corner of
// the face texture, outside the head, where nothing seen from the front
// samples: an azimuthal map of the back half of the head, the back pole at
// the disc's centre and the silhouette seen from the front on its rim, each
// direction around the head at its own angle (the angle of its outline ray).
//
// Why a disc of its own: the shell's hidden vertices used to take their
// colour from single texels of the photo just inside the silhouette, one per
// ray, so every strand of hair, every edge of a pair of glasses and every
// step between hair and skin on the outline ran backwards across the side of
// a turned head as a streak, and the back repeated the front. The disc holds
// those colours smoothed around the head, and fades them, going back, into
// the colour of the top of the head (hair, a cap, or skin), as a head is.
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/model/image.hpp"

namespace fw::model {

/// Where the disc lies in the texture (uv, v up): clear of the head and
/// neck of every face (below the shoulder rays' outline, beside the neck).
struct HeadBackPatch {
  glm::vec2 centre{0.07f, 0.07f};
  float radius = 0.055f;
};
inline constexpr HeadBackPatch kHeadBackPatch{};

/// The uv of a point of the head's back half: `phi` its direction around
/// the head (radians, counter-clockwise from +x seen from the front, as the
/// outline's rays), `t` how far from the back pole (0) toward the
/// silhouette (1).
glm::vec2 head_back_uv(float phi, float t);

/// Whether a uv lies on the disc (a shell vertex whose colour it gives).
bool on_head_back_patch(glm::vec2 uv);

/// Paints the disc, and a margin around it so mipmaps do not blend in what
/// is beside it, from the texture's own colours just inside the head's
/// silhouette: on each outline ray, around the point where the ray's hidden
/// part used to take its colour (`colour_radius`, unseen_colour_radii in
/// head_shell.hpp), only texels whose alpha shows them. Alpha is opaque.
/// @param[in,out] texture  the face texture (sRGB, row 0 at the top)
void paint_head_back(RgbaImage& texture, const TextureFrame& frame, glm::vec2 shell_centre,
                     std::span<const float> colour_radius);

/// The normals a photo's light was seen under at each vertex of `shell`
/// (the shaders' rest normals: a photo is relit by the change in light
/// between them and the posed normals): `normals` themselves, but on the
/// disc the view axis (+z), as for the photo's frontal face. The disc's
/// colours are averages over a side of the head, not the light of any one
/// surface; with the vertices' own normals, the back of a head turned
/// toward the light was relit as if the photo had seen it in shadow, and
/// came out pale, and the other side dark.
std::vector<glm::vec3> photo_light_normals(const Mesh& shell, std::vector<glm::vec3> normals);

}  // namespace fw::model
