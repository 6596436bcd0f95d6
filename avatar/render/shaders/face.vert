#version 300 es
// The one vertex shader of facewire: loaded by the native OSMesa renderer
// (desktop GL with ARB_ES3_compatibility) and by WebGL2 in the browser. It
// gets the same defines as face.frag (see there): FW_ALBEDO, FW_MATTE and
// FW_SPECULAR choose what light it hands on.
precision highp float;

layout(location = 0) in vec3 a_position;     // model units, already morphed
layout(location = 1) in vec3 a_normal;       // of the morphed shape
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_rest_normal;  // of the shape the photo shows

uniform mat4 u_model;            // rigid: head pose, eye rotation
uniform mat4 u_view_projection;
uniform vec3 u_light_direction;  // toward the key light, world space, unit length
uniform vec3 u_camera_position;

out vec3 v_normal;
out vec2 v_uv;
#if defined(FW_ALBEDO) && !defined(FW_MATTE)
#define FW_SKIN_SPECULAR
#endif
#ifdef FW_SKIN_SPECULAR
out float v_fresnel;  // the skin's reflectance toward the camera
#endif
#ifndef FW_ALBEDO
out float v_relight;  // the photo's light changed by the surface's turn
#endif
#if defined(FW_SKIN_SPECULAR) || defined(FW_SPECULAR)
out vec3 v_half;     // between the key light and the camera
#endif

#ifdef FW_SKIN_SPECULAR
// Schlick's Fresnel from skin's normal reflectance of about 0.028
// (refractive index 1.4): the skin's specular strengthens toward grazing
// angles. Per vertex: it changes slowly but at the outline.
const float kSkinF0 = 0.028;

float skin_fresnel(vec3 n, vec3 view) {
  float grazing = 1.0 - clamp(dot(n, view), 0.0, 1.0);
  float g2 = grazing * grazing;
  return kSkinF0 + (1.0 - kSkinF0) * g2 * g2 * grazing;
}
#endif
#ifndef FW_ALBEDO
// The photo already holds its own light. Only a change of the surface's
// direction from the photo's (a turned head, a raised brow, a turned eye)
// changes how much of the key light it catches: the ratio of the two. Per
// vertex: the ratio changes as slowly as the shape does (the photo holds
// the detail), and a fragment then pays one multiplication for it.
//
// The ratio darkens freely but brightens by a tenth at most: "then" takes
// the photo to have been lit by our key light alone, and a photo's light
// is broader (a room's, a flash's), so its texels at a grazing angle (the
// sides of a head seen from the front) are nothing like as dark as that
// says. Up to 1.6 times brighter, the side of a head turned toward the
// light came out pale, a mask's rim.
float relighting(vec3 n, vec3 rest) {
  float now = 0.35 + 0.65 * max(dot(n, u_light_direction), 0.0);
  float then = 0.35 + 0.65 * max(dot(rest, u_light_direction), 0.0);
  return clamp(now / then, 0.45, 1.1);
}
#endif

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  // u_model is a rotation plus translation, so its upper 3x3 turns normals too.
  v_normal = mat3(u_model) * a_normal;
  v_uv = a_uv;
  vec3 view = normalize(u_camera_position - world.xyz);
#ifdef FW_SKIN_SPECULAR
  v_fresnel = skin_fresnel(normalize(v_normal), view);
#endif
#ifndef FW_ALBEDO
  // The photo saw the face frontal and at rest: its normals, unposed. (The
  // inside of the skin's rim, seen on a turned head, takes its outside's.)
  v_relight = relighting(normalize(v_normal), normalize(a_rest_normal));
#endif
#if defined(FW_SKIN_SPECULAR) || defined(FW_SPECULAR)
  v_half = normalize(u_light_direction + view);
#endif
  gl_Position = u_view_projection * world;
}
