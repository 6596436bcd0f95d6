#pragma once
// The HTTP API beside the static files (PROTOCOL.md, "HTTP API"): packages,
// rooms, readiness and metrics. Uploads are asynchronous and live in
// photo_preparation.hpp.
#include <optional>

#include "http_responses.hpp"
#include "server_context.hpp"

namespace fw::server {

/// The answer to a GET, HEAD or DELETE the API serves, or nullopt when the
/// target is not one of its routes.
std::optional<Response> respond_to_api(ServerContext& context, const Request& request);

/// A JSON response.
Response json_response(boost::beast::http::status status, unsigned version, bool keep_alive, std::string body);

}  // namespace fw::server
