#pragma once
// Saved looks over HTTP (PROTOCOL.md 8.2): GET /api/avatars/ID/looks lists
// an avatar's looks, PUT .../looks/NAME saves one (the body, text/plain, is
// its script), DELETE .../looks/NAME deletes one. Every request shows the
// avatar's key (X-Avatar-Key), as a deletion of the avatar does. No
// sockets here: http_session.cpp hands such requests over on a worker
// thread (the store may wait for the disk or Redis) and sends the answer.
#include <optional>
#include <string>
#include <string_view>

#include <boost/asio/thread_pool.hpp>

#include "http_responses.hpp"

namespace fw::server {

struct ApiServices;

/// Whether `target` (a request's path) is one of the saved-look routes.
bool is_look_route(std::string_view target);
/// Whether a request with `method` to `target` carries a look's script: its
/// body is held to kMaxLookScriptBytes before it is read.
bool is_look_save(boost::beast::http::verb method, std::string_view target);

/// The answer to a saved-look request from `peer` (whom the rates count),
/// or nullopt when the target is not one of its routes. Blocking.
std::optional<Response> respond_to_looks(const ApiServices& services, const Request& request,
                                         const std::string& peer);

/// 413 for a look's script of `bytes` (declared or received).
Response oversized_look(unsigned version, std::size_t bytes);

}  // namespace fw::server
