#version 300 es
// The one fragment shader of facewire (see face.vert).
precision highp float;

in vec3 v_normal;
in vec2 v_uv;
in vec3 v_world;

uniform sampler2D u_texture;
uniform vec3 u_camera_position;
uniform vec3 u_light_direction;  // toward the key light, world space
uniform float u_specular;        // 0 for dry skin .. 1 for a wet eye

out vec4 o_colour;

void main() {
  vec4 texel = texture(u_texture, v_uv);
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
