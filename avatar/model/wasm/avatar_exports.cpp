// Avatar models for JavaScript: fw::model::make_avatar_model (the fit and
// the motion-cloned action units) and fw::model::reconstruct_face (the skin
// for one frame's FaceParams) themselves, so that the browser shows exactly
// what the native client shows. web/engine/avatar_model.js wraps these.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <emscripten/emscripten.h>

#include "exports_state.hpp"
#include "face_params_floats.hpp"
#include "unit_morph_ints.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/eye_socket.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/head_back.hpp"
#include "fw/model/mesh.hpp"
#include "fw/model/unit_morphs.hpp"

namespace fw::wasm {
const model::AvatarPackage* find_package(int handle);  // package_exports.cpp
}

namespace {

using fw::model::Mesh;

// Numbers shared with web/engine/avatar_model.js.
enum Part {
  skin = 0, eye_right = 1, eye_left = 2, mouth_cavity = 3, head_shell = 4, eye_socket_right = 5, eye_socket_left = 6,
  part_count = 7
};
enum MeshField { positions = 0, uvs = 1, triangles = 2, normals = 3, photo_light_normals = 4 };
enum FloatsField { texture_frame = 0, eye_centres = 1, eye_shapes = 2, head_centre = 3, head_outline = 4 };
enum IndexField { landmark_vertices = 0, eye_hole_right = 1, eye_hole_left = 2, mouth_slit = 3, triangle_regions = 4 };

struct Avatar {
  fw::model::AvatarModel model;
  std::array<Mesh, 2> eye_sockets;                               // fw/model/eye_socket.hpp, of the fitted face
  std::array<std::vector<glm::vec3>, part_count> rest_normals;  // each mesh's, at rest
  // Under which a photo saw each vertex's colour (head_back.hpp): the rest
  // normals but on the head shell's back.
  std::array<std::vector<glm::vec3>, part_count> photo_light_normals;
  std::array<float, 3> frame_floats{};                           // texture frame
  std::array<float, 6> centres{}, shapes{};
  std::vector<std::uint32_t> regions;
  std::vector<float> frame;  // the last frame: positions 3V, uvs 2V, normals 3V
  // A face-lab preview's simulated skin beyond its action units, carried
  // onto the fit (fw_avatar_set_surface); empty: none.
  std::vector<glm::vec3> surface;
};

fw::wasm::Handles<Avatar> avatars;

const Mesh& mesh_of(const Avatar& a, int part) {
  const fw::model::GenericFace& face = a.model.face;
  switch (part) {
    case eye_socket_right: return a.eye_sockets[0];
    case eye_socket_left: return a.eye_sockets[1];
    case eye_right: return face.eyes[0].mesh;
    case eye_left: return face.eyes[1].mesh;
    case mouth_cavity: return face.mouth_cavity;
    case head_shell: return face.head.mesh;
    default: return face.skin;
  }
}

int add_avatar(fw::model::AvatarModel model) {
  auto a = std::make_unique<Avatar>();
  a->model = std::move(model);
  const fw::model::GenericFace& face = a->model.face;
  for (std::size_t side = 0; side < 2; ++side) a->eye_sockets[side] = fw::model::eye_socket_mesh(face, side);
  for (int part = 0; part < part_count; ++part) {
    a->rest_normals[part] = fw::model::welded_vertex_normals(mesh_of(*a, part));
    a->photo_light_normals[part] = part == head_shell
                                       ? fw::model::photo_light_normals(face.head.mesh, a->rest_normals[part])
                                       : a->rest_normals[part];
  }
  a->frame_floats = {face.texture_frame.origin.x, face.texture_frame.origin.y, face.texture_frame.size};
  for (std::size_t side = 0; side < 2; ++side) {
    for (int k = 0; k < 3; ++k) a->centres[side * 3 + k] = face.eyes[side].centre[k];
    a->shapes[side * 2] = face.eyes[side].radius;
    a->shapes[side * 2 + 1] = face.eyes[side].cap_angle_rad;
  }
  for (const fw::model::FaceRegion r : face.triangle_regions) a->regions.push_back(static_cast<std::uint32_t>(r));
  return avatars.add(std::move(a));
}

template <typename T>
std::span<const float> as_floats(const std::vector<T>& v) {
  return {reinterpret_cast<const float*>(v.data()), v.size() * sizeof(T) / sizeof(float)};
}

std::span<const float> mesh_floats(const Avatar& a, int part, int field) {
  const Mesh& mesh = mesh_of(a, part);
  if (field == positions) return as_floats(mesh.positions);
  if (field == uvs) return as_floats(mesh.uvs);
  if (field == normals) return as_floats(a.rest_normals[static_cast<std::size_t>(part)]);
  if (field == photo_light_normals) return as_floats(a.photo_light_normals[static_cast<std::size_t>(part)]);
  return {};
}

std::span<const float> avatar_floats(const Avatar& a, int which) {
  switch (which) {
    case texture_frame: return a.frame_floats;
    case eye_centres: return a.centres;
    case eye_shapes: return a.shapes;
    case head_centre: return {&a.model.face.head.centre.x, 2};
    case head_outline: return a.model.face.head.outline;
    default: return {};
  }
}

std::span<const std::uint32_t> avatar_indices(const Avatar& a, int which) {
  const fw::model::GenericFace& face = a.model.face;
  switch (which) {
    case landmark_vertices: return face.landmark_vertices;
    case eye_hole_right: return face.eye_holes[0];
    case eye_hole_left: return face.eye_holes[1];
    case mouth_slit: return face.mouth_slit;
    case triangle_regions: return a.regions;
    default: return {};
  }
}

}  // namespace

extern "C" {

/// The avatar of a parsed package. @return a handle, or 0 and fw_last_error()
EMSCRIPTEN_KEEPALIVE int fw_avatar_from_package(int package_handle) {
  const auto* p = fw::wasm::find_package(package_handle);
  if (!p) return 0;
  return add_avatar(fw::model::make_avatar_model(fw::model::generic_face(), p->fitted_vertices, p->head_outline));
}

/// The generic face itself, for avatars without a package.
EMSCRIPTEN_KEEPALIVE int fw_avatar_generic() { return add_avatar(fw::model::generic_avatar_model()); }

EMSCRIPTEN_KEEPALIVE void fw_avatar_release(int handle) { avatars.release(handle); }

/// A static mesh's floats (positions, uvs, rest normals) of one part.
EMSCRIPTEN_KEEPALIVE const float* fw_avatar_mesh_floats(int handle, int part, int field) {
  const Avatar* a = avatars.find(handle);
  return a ? mesh_floats(*a, part, field).data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE int fw_avatar_mesh_floats_count(int handle, int part, int field) {
  const Avatar* a = avatars.find(handle);
  return a ? static_cast<int>(mesh_floats(*a, part, field).size()) : 0;
}
/// A part's triangles, three vertex indices each.
EMSCRIPTEN_KEEPALIVE const std::uint32_t* fw_avatar_triangles(int handle, int part) {
  const Avatar* a = avatars.find(handle);
  return a ? &mesh_of(*a, part).triangles.data()->x : nullptr;
}
EMSCRIPTEN_KEEPALIVE int fw_avatar_triangles_count(int handle, int part) {
  const Avatar* a = avatars.find(handle);
  return a ? static_cast<int>(mesh_of(*a, part).triangles.size() * 3) : 0;
}

EMSCRIPTEN_KEEPALIVE const float* fw_avatar_floats(int handle, int which) {
  const Avatar* a = avatars.find(handle);
  return a ? avatar_floats(*a, which).data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE int fw_avatar_floats_count(int handle, int which) {
  const Avatar* a = avatars.find(handle);
  return a ? static_cast<int>(avatar_floats(*a, which).size()) : 0;
}

EMSCRIPTEN_KEEPALIVE const std::uint32_t* fw_avatar_indices(int handle, int which) {
  const Avatar* a = avatars.find(handle);
  return a ? avatar_indices(*a, which).data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE int fw_avatar_indices_count(int handle, int which) {
  const Avatar* a = avatars.find(handle);
  return a ? static_cast<int>(avatar_indices(*a, which).size()) : 0;
}

/// One action unit channel's cloned morph: field 0 vertex_delta (3V), 1 uv_delta (2V).
EMSCRIPTEN_KEEPALIVE const float* fw_avatar_morph(int handle, int channel, int field) {
  const Avatar* a = avatars.find(handle);
  if (!a || channel < 0 || channel >= static_cast<int>(fw::codec::kAuChannelCount)) return nullptr;
  const fw::model::Morph& m = a->model.morphs[static_cast<std::size_t>(channel)];
  return field == 0 ? as_floats(m.vertex_delta).data() : as_floats(m.uv_delta).data();
}

/// The skin for one frame: reconstruct_face, then the normals the renderer
/// computes from it (fw::model::vertex_normals). Takes FaceParams as 53
/// floats (face_params_floats.hpp).
/// @return positions (3V), uvs (2V) and normals (3V) back to back, valid
///         until the next frame of this avatar; null for an unknown handle
EMSCRIPTEN_KEEPALIVE const float* fw_avatar_frame(int handle, const float* params) {
  Avatar* a = avatars.find(handle);
  if (!a) return nullptr;
  fw::model::FaceShape shape = fw::model::reconstruct_face(a->model, fw::wasm::face_params_from_floats(params));
  if (a->surface.size() == shape.positions.size())
    for (std::size_t v = 0; v < a->surface.size(); ++v) shape.positions[v] += a->surface[v];
  Mesh mesh;
  mesh.positions = shape.positions;
  mesh.triangles = a->model.face.skin.triangles;
  const std::vector<glm::vec3> frame_normals = fw::model::vertex_normals(mesh);
  a->frame.clear();
  for (const auto part : {as_floats(shape.positions), as_floats(shape.uvs), as_floats(frame_normals)})
    a->frame.insert(a->frame.end(), part.begin(), part.end());
  return a->frame.data();
}

/// The avatar's redefined units (server/PROTOCOL.md 5.17; fw/model/unit_morphs.hpp),
/// from a unit morphs message's units as `count` int32s: the number of
/// units, then per unit its channel and its number of moves, then per move
/// the vertex and dx, dy, dz in the wire's steps. No units (`count` 1, a 0)
/// restores the shipped units. Applies to the frames that follow.
/// @return 1, or 0 and fw_last_error() (a short or malformed list, a
///         vertex past the face, an unknown handle)
EMSCRIPTEN_KEEPALIVE int fw_avatar_set_unit_morphs(int handle, const std::int32_t* data, int count) {
  Avatar* a = avatars.find(handle);
  if (!a) return 0;
  fw::codec::UnitMorphs message;
  std::string error;
  if (!fw::wasm::unit_morphs_from_ints({data, static_cast<std::size_t>(std::max(count, 0))}, message, error)) {
    fw::wasm::set_error(error);
    return 0;
  }
  const fw::model::GenericFace& generic = fw::model::generic_face();
  const auto set = fw::model::unit_morph_set(message, generic.skin.positions.size(), error);
  if (!set) {
    fw::wasm::set_error(error);
    return 0;
  }
  fw::model::set_unit_morphs(a->model, generic, *set);
  return 1;
}

/// A face-lab preview's skin beyond its frames' action units (server/PROTOCOL.md
/// 5.18), from a preview surface message's moves as `count` int32s: the
/// number of moves, then per move the generic vertex and dx, dy, dz in the
/// wire's steps; carried onto the fit and added to the frames that follow.
/// No moves (`count` 1, a 0) clears it.
/// @return 1, or 0 and fw_last_error() (a malformed list, a vertex past the face, an unknown handle)
EMSCRIPTEN_KEEPALIVE int fw_avatar_set_surface(int handle, const std::int32_t* data, int count) {
  Avatar* a = avatars.find(handle);
  if (!a) return 0;
  std::vector<fw::codec::UnitMorphs::Move> moves;
  std::string error;
  if (!fw::wasm::surface_moves_from_ints({data, static_cast<std::size_t>(std::max(count, 0))}, moves, error)) {
    fw::wasm::set_error(error);
    return 0;
  }
  auto surface =
      fw::model::carried_surface(a->model, moves, fw::model::generic_face().skin.positions.size(), error);
  if (!surface) {
    fw::wasm::set_error(error);
    return 0;
  }
  a->surface = moves.empty() ? std::vector<glm::vec3>{} : std::move(*surface);
  return 1;
}

EMSCRIPTEN_KEEPALIVE int fw_face_params_floats() { return static_cast<int>(fw::wasm::kFaceParamsFloats); }

}
