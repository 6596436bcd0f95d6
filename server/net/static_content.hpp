#pragma once
// The files the HTTP server hands out: the web client, the generic face
// asset and the shaders, all compiled into the binary so `make run` needs
// nothing beside it.
#include <optional>
#include <string>
#include <string_view>

namespace fw::server {

struct StaticFile {
  std::string_view content_type;
  std::string_view body;
  std::string etag;  ///< a strong validator derived from the body
};

/// A file of `content_type` whose body is `body` (which must outlive it), with its ETag.
StaticFile static_file(std::string_view content_type, std::string_view body);

/// The file served at `target` (the request path, query string ignored).
std::optional<StaticFile> find_static_file(std::string_view target);

}  // namespace fw::server
