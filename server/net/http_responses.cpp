#include "http_responses.hpp"

#include "static_content.hpp"

namespace fw::server {

namespace http = boost::beast::http;

namespace {

constexpr const char* kServerName = "facewire";

Response text_response(http::status status, unsigned version, bool keep_alive, std::string body) {
  Response response{status, version};
  response.set(http::field::server, kServerName);
  response.set(http::field::content_type, "text/plain; charset=utf-8");
  response.keep_alive(keep_alive);
  response.body() = std::move(body);
  response.prepare_payload();
  return response;
}

}  // namespace

Response error_response(http::status status, unsigned version, const std::string& message) {
  return text_response(status, version, false, message + "\n");
}

Response respond_to(const Request& request) {
  const bool head = request.method() == http::verb::head;
  if (request.method() != http::verb::get && !head) {
    Response response = text_response(http::status::method_not_allowed, request.version(), request.keep_alive(),
                                      "only GET and HEAD are served here (uploads: POST /api/avatars)\n");
    response.set(http::field::allow, "GET, HEAD");
    return response;
  }
  const std::string_view target(request.target().data(), request.target().size());
  if (target == "/healthz") return text_response(http::status::ok, request.version(), request.keep_alive(), "ok\n");

  const auto file = find_static_file(target);
  if (!file)
    return text_response(http::status::not_found, request.version(), request.keep_alive(),
                         "nothing at " + std::string(target) + "\n");
  if (request[http::field::if_none_match] == file->etag) {
    Response response{http::status::not_modified, request.version()};
    response.set(http::field::server, kServerName);
    response.set(http::field::etag, file->etag);
    response.keep_alive(request.keep_alive());
    return response;
  }
  Response response{http::status::ok, request.version()};
  response.set(http::field::server, kServerName);
  response.set(http::field::content_type, std::string(file->content_type));
  response.set(http::field::etag, file->etag);
  response.set(http::field::cache_control, "no-cache");  // revalidate: cheap with the ETag
  response.keep_alive(request.keep_alive());
  if (head) {
    response.content_length(file->body.size());
  } else {
    response.body() = std::string(file->body);
    response.prepare_payload();
  }
  return response;
}

}  // namespace fw::server
