#include "static_content.hpp"

#include <array>
#include <cstdio>
#include <functional>

#include "fw/model/generic_face.hpp"
#include "web_files.hpp"

namespace fw::embedded {
extern const std::string_view shader_face_vert;  // avatar/render/shaders/face.vert
extern const std::string_view shader_face_frag;  // avatar/render/shaders/face.frag
}  // namespace fw::embedded

namespace fw::server {
namespace {

struct Route {
  std::string_view path;
  std::string_view content_type;
  const std::string_view* body;
};

const std::string_view kGenericFace = model::generic_face_asset_json();

// What the browser loads from elsewhere than web/: the generic face of
// avatar/model and the shaders of avatar/render, the very files the native
// renderer uses.
const std::array<Route, 3> kSharedFiles = {{
    {"/generic_face.json", "application/json", &kGenericFace},
    {"/shaders/face.vert", "text/plain; charset=utf-8", &embedded::shader_face_vert},
    {"/shaders/face.frag", "text/plain; charset=utf-8", &embedded::shader_face_frag},
}};

struct TypeByExtension {
  std::string_view extension;
  std::string_view content_type;
};

// The types of what embed_web_files.cmake embeds; module scripts must be
// served as JavaScript or the browser refuses them.
constexpr std::array<TypeByExtension, 6> kTypes = {{
    {".html", "text/html; charset=utf-8"},
    {".js", "text/javascript; charset=utf-8"},
    {".mjs", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},
    {".json", "application/json"},
    {".wasm", "application/wasm"},
}};

std::string_view content_type_of(std::string_view path) {
  for (const auto& type : kTypes)
    if (path.ends_with(type.extension)) return type.content_type;
  return "application/octet-stream";
}

std::string etag_of(std::string_view body) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "\"%016zx\"", std::hash<std::string_view>{}(body));
  return buffer;
}

}  // namespace

StaticFile static_file(std::string_view content_type, std::string_view body) {
  return StaticFile{content_type, body, etag_of(body)};
}

std::optional<StaticFile> find_static_file(std::string_view target) {
  std::string_view path = target.substr(0, target.find('?'));
  if (path == "/") path = "/index.html";
  for (const Route& route : kSharedFiles)
    if (route.path == path) return static_file(route.content_type, *route.body);
  for (const WebFile& file : web_files())
    if (file.path == path) return static_file(content_type_of(path), *file.body);
  return std::nullopt;
}

}  // namespace fw::server
