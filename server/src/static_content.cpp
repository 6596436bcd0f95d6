#include "static_content.hpp"

#include <array>
#include <cstdio>
#include <functional>

#include "fw/model/generic_face.hpp"

namespace fw::embedded {
extern const std::string_view web_index_html;    // web/index.html
extern const std::string_view web_face_preview_js;  // web/face_preview.js
extern const std::string_view web_mat4_js;          // web/mat4.js
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

const std::array<Route, 7> kRoutes = {{
    {"/", "text/html; charset=utf-8", &embedded::web_index_html},
    {"/index.html", "text/html; charset=utf-8", &embedded::web_index_html},
    {"/face_preview.js", "text/javascript; charset=utf-8", &embedded::web_face_preview_js},
    {"/mat4.js", "text/javascript; charset=utf-8", &embedded::web_mat4_js},
    {"/generic_face.json", "application/json", &kGenericFace},
    {"/shaders/face.vert", "text/plain; charset=utf-8", &embedded::shader_face_vert},
    {"/shaders/face.frag", "text/plain; charset=utf-8", &embedded::shader_face_frag},
}};

std::string etag_of(std::string_view body) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "\"%016zx\"", std::hash<std::string_view>{}(body));
  return buffer;
}

}  // namespace

std::optional<StaticFile> find_static_file(std::string_view target) {
  const std::string_view path = target.substr(0, target.find('?'));
  for (const Route& route : kRoutes)
    if (route.path == path) return StaticFile{route.content_type, *route.body, etag_of(*route.body)};
  return std::nullopt;
}

}  // namespace fw::server
