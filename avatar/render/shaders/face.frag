#version 300 es
// The one fragment shader of facewire (see face.vert), compiled once per
// kind of part with these defines inserted after the #version line (of
// both stages):
//   FW_CLOSED_LID  the skin: fades in the closed lids
//   FW_BLOOD       the skin in a frame with blush or pallor
//   FW_SPECULAR    an eyeball: a wet highlight and a catch-light
//   FW_MATTE       a part without the skin's specular (the mouth cavity,
//                  the head shell): the same light as with u_skin_specular
//                  0, for less work per fragment
//   FW_ALBEDO      a face whose textures are albedo (a procedural face):
//                  lit by sky, ground and a key light; without it the
//                  textures are a photo, which holds its own light
//   FW_ALPHA_TEST  no multisampling: alpha under 0.5 is a hole
//   FW_SQUARE_ROOT_COLOUR  colour textures hold the square root of linear
//                  light (the native renderer's, for llvmpipe's speed);
//                  without it they are sRGB textures, decoded on lookup
// and none but FW_ALBEDO (and natively FW_MATTE) for the mouth cavity and
// the head shell. Variants
// rather than branches on uniforms: a software rasteriser runs both sides
// of a branch for every fragment, and a frame is mostly fragments.
//
// Colour is computed in linear light (colour textures are sRGB textures,
// decoded on lookup, or square roots squared here) and encoded to sRGB here, because both targets store
// what they are given: a WebGL canvas cannot be sRGB, and natively an sRGB
// framebuffer makes every multisampled fragment cost a quarter more.
precision highp float;

in vec3 v_normal;
in vec2 v_uv;
#if defined(FW_ALBEDO) && !defined(FW_MATTE)
#define FW_SKIN_SPECULAR
#endif
#ifdef FW_SKIN_SPECULAR
in float v_fresnel;
#endif
#ifndef FW_ALBEDO
in float v_relight;
#endif
#if defined(FW_SKIN_SPECULAR) || defined(FW_SPECULAR)
in vec3 v_half;
#endif

uniform sampler2D u_texture;
uniform vec3 u_light_direction;  // toward the key light, world space, unit length

#ifdef FW_SPECULAR
uniform float u_specular;        // 0 .. 1 for a wet eye
#endif
#ifdef FW_CLOSED_LID
uniform sampler2D u_closed_lid;  // skin over the eyes, placed at u_closed_lid_rect
uniform vec4 u_closed_lid_rect;  // u0, v0, u1, v1 of the skin texture
uniform vec2 u_lid_closure;      // person's right, left: 0 open .. 1 closed
#endif
#ifdef FW_BLOOD
uniform sampler2D u_masks_a;     // forehead, left cheek, right cheek (linear)
uniform sampler2D u_masks_b;     // nose, sides, whole face (linear)
uniform vec4 u_blush_a;          // forehead, left cheek, right cheek, nose: 0..1
uniform float u_blush_sides;
uniform float u_pallor;          // 0..1
#endif

out vec4 o_colour;

// Blood in the skin (the vascular-expressions paper's colour signal), as
// light passing through it: more blood absorbs green and blue far more than
// red (Beer-Lambert, haemoglobin's absorption), so a blush reddens and
// darkens a little, in proportion to each region's smooth Bezier shade;
// less blood (pallor) drains the colour toward a lighter, cooler grey.
#ifdef FW_BLOOD
const vec3 kBloodAbsorption = vec3(0.18, 1.0, 0.82);
const float kMaxBlood = 0.75;

vec3 vascular(vec3 linear_colour) {
  // The shade rises from 0 at a region's border; raised to 1.5 it also
  // leaves the border with zero slope, so no region shows an edge.
  vec4 b_raw = texture(u_masks_b, v_uv);
  vec4 a_raw = texture(u_masks_a, v_uv);
  vec4 a = a_raw * sqrt(a_raw);
  vec4 b = b_raw * sqrt(b_raw);
  float blood = dot(a.rgb, u_blush_a.xyz) + b.r * u_blush_a.w + b.g * u_blush_sides;
  vec3 colour = linear_colour * exp(-kBloodAbsorption * kMaxBlood * blood);
  float luminance = dot(colour, vec3(0.2126, 0.7152, 0.0722));
  vec3 pale = vec3(luminance) * vec3(0.97, 1.0, 1.04) * 1.1;
  return mix(colour, pale, 0.65 * u_pallor * b_raw.b);
}
#endif

#ifdef FW_ALBEDO
// Light for albedo: a sky-and-ground (hemisphere) ambient, the common
// real-time stand-in for light from everywhere (cool from above, warm
// bounce from below), plus a key light above and to the side, wrapped
// (Lambert over a wider range) so the terminator is soft as it is on skin,
// where light scatters under the surface. Together about 1 on a frontal
// face, so the texture's colour is what the front of the face shows.
const vec3 kSky = vec3(0.40, 0.43, 0.48);
const vec3 kGround = vec3(0.16, 0.13, 0.11);
const vec3 kKey = vec3(0.86, 0.83, 0.78);
const float kWrap = 0.5;  // (n.l + w) / (1 + w)

// Skin's specular: a broad, low lobe (Weyrich et al. 2006, "Analysis of
// human faces using a measurement-based skin reflectance model": roughness
// about 0.3-0.45, here Blinn-Phong's 16th power) times Schlick's Fresnel
// (v_fresnel, face.vert). Its scale (the lobe's normalisation and the
// key's strength) is a uniform set per part: the face's skin has it, the
// head shell, mostly hair, does not (on hair the lobe read as a plastic
// helmet's sheen), and one program may draw both; natively the mouth and
// the shell use FW_MATTE instead.
#ifdef FW_SKIN_SPECULAR
uniform float u_skin_specular;
#endif

vec3 albedo_light(vec3 albedo, vec3 n) {
  float n_dot_l = dot(n, u_light_direction);
  // Constants folded: mix(ground, sky, n.y / 2 + 1/2) and (n.l + w) / (1 + w).
  vec3 ambient = 0.5 * (kSky + kGround) + 0.5 * (kSky - kGround) * n.y;
  vec3 irradiance = ambient + kKey * max(n_dot_l * (1.0 / (1.0 + kWrap)) + kWrap / (1.0 + kWrap), 0.0);
#ifndef FW_SKIN_SPECULAR
  return albedo * irradiance;
#else
  float h = max(dot(n, v_half), 0.0);
  h *= h;
  h *= h;
  h *= h;
  h *= h;
  return albedo * irradiance + kKey * (u_skin_specular * v_fresnel * h * max(n_dot_l, 0.0));
#endif
}
#endif

// The multisample resolve then averages encoded values: an edge pixel comes
// out a little darker than a linear average would make it, an accepted cost.
//
// The curve's power 1/2.4 is fitted with square roots (within 0.25 of an
// 8-bit step, so a channel differs from the exact curve's by at most one
// step, in about one value of sixty): pow() is a logarithm and an
// exponential, and a software renderer runs it for every fragment it
// rasterises, hidden ones included under multisampling. Fit: chilliant,
// "sRGB approximations for HLSL" (2012).
vec3 encode_srgb(vec3 linear_colour) {
  vec3 c = clamp(linear_colour, 0.0, 1.0);
  vec3 s1 = sqrt(c), s2 = sqrt(s1), s3 = sqrt(s2);
  vec3 curve = 0.662002687 * s1 + 0.684122060 * s2 - 0.323583601 * s3 - 0.0225411470 * c;
  return mix(c * 12.92, curve, step(vec3(0.0031308), c));
}

vec4 colour_texel(sampler2D colour_texture, vec2 uv) {
  vec4 texel = texture(colour_texture, uv);
#ifdef FW_SQUARE_ROOT_COLOUR
  texel.rgb *= texel.rgb;
#endif
  return texel;
}

void main() {
  vec4 texel = colour_texel(u_texture, v_uv);
#ifdef FW_CLOSED_LID
  // Closing lids: the skin that was over the eye in the photo fills the
  // eye hole of the texture. Looked up at rest coordinates (v_uv), like
  // the skin itself, so it moves with the lids and never lays the rest
  // pose over a face that has moved (a brow raised during a blink).
  vec2 lid_uv = (v_uv - u_closed_lid_rect.xy) / (u_closed_lid_rect.zw - u_closed_lid_rect.xy);
  if (all(greaterThanEqual(lid_uv, vec2(0.0))) && all(lessThanEqual(lid_uv, vec2(1.0)))) {
    float closure = v_uv.x < 0.5 ? u_lid_closure.x : u_lid_closure.y;
    vec2 edge = min(lid_uv, vec2(1.0) - lid_uv);
    float cover = closure * smoothstep(0.0, 0.12, min(edge.x, edge.y));
    texel.rgb = mix(texel.rgb, colour_texel(u_closed_lid, lid_uv).rgb, cover);
    texel.a = max(texel.a, cover);
  }
#endif
#ifdef FW_BLOOD
  texel.rgb = vascular(texel.rgb);
#endif
  // Alpha marks the holes (the eyes) and the head's outline: what is behind
  // shows through. With multisampling, alpha becomes the share of samples
  // covered (alpha to coverage), so outlines are smooth instead of a stair
  // of whole pixels.
#ifdef FW_ALPHA_TEST
  if (texel.a < 0.5) discard;
#endif
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
#ifdef FW_ALBEDO
  vec3 colour = albedo_light(texel.rgb, n);
#else
  vec3 colour = texel.rgb * v_relight;
#endif
#ifdef FW_SPECULAR
  // A wet eye reflects the key light: a gentle sheen (the 16th power) and a
  // catch-light, the small bright image of the light (as of a window) on
  // the cornea, 6 degrees of the surface's turn across, soft to 10. Both lie
  // where the cornea faces halfway between the light and the camera, so
  // they stay on the light's side and shift only with the cornea's bulge as
  // the eye turns (as the first Purkinje image does), never painted on the
  // iris. The photo cannot hold either: the eye turns.
  float h = max(dot(n, v_half), 0.0);
  float h16 = h * h;
  h16 *= h16;
  h16 *= h16;
  h16 *= h16;
  float catch_light = smoothstep(0.9848, 0.9945, h);  // cos 10 and 6 degrees
  colour += vec3(u_specular * (0.06 * h16 + catch_light));
#endif
  o_colour = vec4(encode_srgb(colour), texel.a);
}
