#version 300 es
// The one vertex shader of facewire: loaded by the native OSMesa renderer
// (desktop GL with ARB_ES3_compatibility) and by WebGL2 in the browser.
precision highp float;

layout(location = 0) in vec3 a_position;     // model units, already morphed
layout(location = 1) in vec3 a_normal;       // of the morphed shape
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec3 a_rest_normal;  // of the shape the photo shows

uniform mat4 u_model;            // rigid: head pose, eye rotation
uniform mat4 u_view_projection;

out vec3 v_normal;
out vec3 v_rest_normal;
out vec2 v_uv;
out vec3 v_world;

void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  // u_model is a rotation plus translation, so its upper 3x3 turns normals too.
  v_normal = mat3(u_model) * a_normal;
  // The photo saw the face frontal and at rest: its normals, unposed.
  v_rest_normal = a_rest_normal;
  v_uv = a_uv;
  gl_Position = u_view_projection * world;
}
