#version 300 es
// The one fragment shader of facewire (see face.vert). u_layer picks the
// part: the skin (eye holes, closed lids, blood colour), an eyeball, or the
// mouth cavity.
precision highp float;

in vec3 v_normal;
in vec2 v_uv;
in vec3 v_world;

uniform int u_layer;             // 0 skin, 1 eyeball, 2 mouth
uniform sampler2D u_texture;
uniform vec3 u_camera_position;
uniform vec3 u_light_direction;  // toward the key light, world space
uniform float u_specular;        // 0 for dry skin .. 1 for a wet eye

// Skin only.
uniform sampler2D u_closed_lid;  // skin over the eyes, placed at u_closed_lid_rect
uniform vec4 u_closed_lid_rect;  // u0, v0, u1, v1 of the skin texture
uniform vec2 u_lid_closure;      // person's right, left: 0 open .. 1 closed
uniform sampler2D u_masks_a;     // forehead, left cheek, right cheek
uniform sampler2D u_masks_b;     // nose, sides, whole face
uniform vec4 u_blush_a;          // forehead, left cheek, right cheek, nose: 0..1
uniform float u_blush_sides;
uniform float u_pallor;          // 0..1

out vec4 o_colour;

// Blood in the skin: blushing reddens and saturates, pallor greys and
// lightens (the vascular-expressions paper's colour signal).
vec3 vascular(vec3 colour) {
  vec4 a = texture(u_masks_a, v_uv);
  vec4 b = texture(u_masks_b, v_uv);
  float blush = clamp(dot(a.rgb, u_blush_a.xyz) + b.r * u_blush_a.w + b.g * u_blush_sides, 0.0, 1.0);
  colour = mix(colour, colour * vec3(1.2, 0.78, 0.8), 0.85 * blush);
  float grey = dot(colour, vec3(0.299, 0.587, 0.114));
  vec3 pale = vec3(grey) * vec3(0.98, 1.0, 1.04) + vec3(0.06);
  return mix(colour, pale, 0.75 * u_pallor * b.b);
}

void main() {
  vec4 texel = texture(u_texture, v_uv);
  if (u_layer == 0) {
    // Closing lids: the skin that was over the eye in the photo fills the
    // eye hole of the texture. Looked up at rest coordinates (v_uv), like
    // the skin itself, so it moves with the lids and never lays the rest
    // pose over a face that has moved (a brow raised during a blink).
    vec2 lid_uv = (v_uv - u_closed_lid_rect.xy) / (u_closed_lid_rect.zw - u_closed_lid_rect.xy);
    if (all(greaterThanEqual(lid_uv, vec2(0.0))) && all(lessThanEqual(lid_uv, vec2(1.0)))) {
      float closure = v_uv.x < 0.5 ? u_lid_closure.x : u_lid_closure.y;
      vec2 edge = min(lid_uv, vec2(1.0) - lid_uv);
      float cover = closure * smoothstep(0.0, 0.12, min(edge.x, edge.y));
      texel.rgb = mix(texel.rgb, texture(u_closed_lid, lid_uv).rgb, cover);
      texel.a = max(texel.a, cover);
    }
    texel.rgb = vascular(texel.rgb);
  }
  // Alpha marks the holes (the eyes): the layer behind shows through.
  if (texel.a < 0.5) discard;
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 l = normalize(u_light_direction);
  vec3 v = normalize(u_camera_position - v_world);
  float key = max(dot(n, l), 0.0);
  float fill = max(dot(n, normalize(vec3(-0.6, 0.1, 0.8))), 0.0);
  float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0);
  float highlight = u_specular * pow(max(dot(n, normalize(l + v)), 0.0), 60.0);
  vec3 colour = texel.rgb * (0.25 + 0.7 * key + 0.2 * fill + 0.1 * rim) + vec3(highlight);
  o_colour = vec4(colour, 1.0);
}
