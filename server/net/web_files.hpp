#pragma once
// The files of web/, compiled into the server: the table is generated at
// build time by server/cmake/embed_web_files.cmake, one entry per file.
#include <span>
#include <string_view>

namespace fw::server {

struct WebFile {
  std::string_view path;        ///< the URL path, e.g. "/lobby/lobby.js"
  const std::string_view* body;  ///< the file's bytes
};

/// Every embedded web file, sorted by path.
std::span<const WebFile> web_files();

}  // namespace fw::server
