#pragma once
// The address `facewire-client join` connects to: ws://HOST:PORT/[PATH]
// (WebSocket, the browser's protocol) or tcp://HOST:PORT (length-prefixed
// messages on the server's native port).
#include <string>

namespace fw::client {

struct ServerUrl {
  enum class Scheme { websocket, tcp };
  Scheme scheme = Scheme::websocket;
  std::string host;
  std::string port;
  std::string path = "/";  ///< WebSocket only: the upgrade request's target
  std::string text;        ///< as it was written, for what the person reads
};

/// @return false and `error` (what is wrong and what a URL looks like)
bool parse_server_url(const std::string& text, ServerUrl& url, std::string& error);

}  // namespace fw::client
