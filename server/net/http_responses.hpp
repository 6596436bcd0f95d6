#pragma once
// Building HTTP responses: the answer to a request, and error answers.
#include <string>

#include <boost/beast/http.hpp>

namespace fw::server {

using Request = boost::beast::http::request<boost::beast::http::string_body>;
using Response = boost::beast::http::response<boost::beast::http::string_body>;

/// The response to a well-formed request: static files, /healthz, 404, 405.
Response respond_to(const Request& request);

/// A plain-text answer to `request` (its HTTP version, kept alive as it asks).
Response plain_response(boost::beast::http::status status, const Request& request, std::string body);
/// 204 No Content: what a deletion answers.
Response no_content_response(const Request& request);

/// A plain-text error that says what was wrong and what to do; the
/// connection closes after it.
Response error_response(boost::beast::http::status status, unsigned version, const std::string& message);

}  // namespace fw::server
