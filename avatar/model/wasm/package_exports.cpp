// Avatar packages for JavaScript: fw::model::parse_avatar_package itself
// (the same checks and messages as every native client), and read access to
// what it parsed. web/engine/avatar_package.js wraps these.
#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include <emscripten/emscripten.h>

#include "exports_state.hpp"
#include "fw/model/avatar_package.hpp"

namespace {

fw::wasm::Handles<fw::model::AvatarPackage> packages;
fw::model::PackageRefusal last_refusal = fw::model::PackageRefusal::damaged;

// Numbers shared with web/engine/avatar_package.js.
enum PackageFloats { fitted_vertices = 0, landmarks = 1, head_outline = 2, closed_lid_rect = 3 };
enum PackageMember { face_texture = 0, closed_lid = 1, eye = 2, mouth = 3, colour_masks_a = 4, colour_masks_b = 5,
                     preview = 6 };

std::span<const float> floats_of(const fw::model::AvatarPackage& p, int which) {
  switch (which) {
    case fitted_vertices: return {&p.fitted_vertices.data()->x, p.fitted_vertices.size() * 2};
    case landmarks: return {&p.landmarks.data()->x, p.landmarks.size() * 2};
    case head_outline: return p.head_outline;
    case closed_lid_rect: return {&p.closed_lid_rect.x, 4};
    default: return {};
  }
}

const fw::model::PackageImage* member_of(const fw::model::AvatarPackage& p, int which) {
  switch (which) {
    case face_texture: return &p.face_texture;
    case closed_lid: return &p.closed_lid;
    case eye: return &p.eye;
    case mouth: return &p.mouth;
    case colour_masks_a: return &p.colour_masks_a;
    case colour_masks_b: return &p.colour_masks_b;
    case preview: return &p.preview;
    default: return nullptr;
  }
}

}  // namespace

namespace fw::wasm {
const model::AvatarPackage* find_package(int handle) { return packages.find(handle); }
}  // namespace fw::wasm

extern "C" {

/// @return a package handle, or 0 with fw_last_error() and fw_last_refusal()
EMSCRIPTEN_KEEPALIVE int fw_package_parse(const std::uint8_t* bytes, int size) {
  auto package = std::make_unique<fw::model::AvatarPackage>();
  std::string error;
  if (!fw::model::parse_avatar_package({bytes, static_cast<std::size_t>(size)}, *package, error, last_refusal)) {
    fw::wasm::set_error(error);
    return 0;
  }
  return packages.add(std::move(package));
}

/// Why the last parse failed: fw::model::PackageRefusal's value.
EMSCRIPTEN_KEEPALIVE int fw_last_refusal() { return static_cast<int>(last_refusal); }

EMSCRIPTEN_KEEPALIVE void fw_package_release(int handle) { packages.release(handle); }

/// 0 version, 1 generic_face_version, 2 texture_light (fw::model::TextureLight's value).
EMSCRIPTEN_KEEPALIVE int fw_package_int(int handle, int which) {
  const auto* p = packages.find(handle);
  if (!p) return -1;
  if (which == 2) return static_cast<int>(p->texture_light);
  return which == 0 ? p->version : p->generic_face_version;
}

/// sRGB bytes: 0 skin_tone, 1 iris_colour.
EMSCRIPTEN_KEEPALIVE const std::uint8_t* fw_package_rgb(int handle, int which) {
  const auto* p = packages.find(handle);
  if (!p) return nullptr;
  return which == 0 ? p->skin_tone.data() : p->iris_colour.data();
}

EMSCRIPTEN_KEEPALIVE const float* fw_package_floats(int handle, int which) {
  const auto* p = packages.find(handle);
  return p ? floats_of(*p, which).data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE int fw_package_floats_count(int handle, int which) {
  const auto* p = packages.find(handle);
  return p ? static_cast<int>(floats_of(*p, which).size()) : 0;
}

/// An image member's encoded bytes and media type ("" and 0 bytes if absent).
EMSCRIPTEN_KEEPALIVE const std::uint8_t* fw_package_member(int handle, int which) {
  const auto* p = packages.find(handle);
  const auto* m = p ? member_of(*p, which) : nullptr;
  return m ? m->bytes.data() : nullptr;
}
EMSCRIPTEN_KEEPALIVE int fw_package_member_size(int handle, int which) {
  const auto* p = packages.find(handle);
  const auto* m = p ? member_of(*p, which) : nullptr;
  return m ? static_cast<int>(m->bytes.size()) : 0;
}
EMSCRIPTEN_KEEPALIVE const char* fw_package_member_type(int handle, int which) {
  const auto* p = packages.find(handle);
  const auto* m = p ? member_of(*p, which) : nullptr;
  return m ? m->type.c_str() : "";
}

}
