#include "http_responses.hpp"

#include <fstream>
#include <iterator>

#include "speech_data.hpp"
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

Response plain_response(http::status status, const Request& request, std::string body) {
  return text_response(status, request.version(), request.keep_alive(), std::move(body));
}

Response no_content_response(const Request& request) {
  Response response{http::status::no_content, request.version()};
  response.set(http::field::server, kServerName);
  response.keep_alive(request.keep_alive());
  response.prepare_payload();
  return response;
}

namespace {

Response file_response(const Request& request, const StaticFile& file) {
  if (request[http::field::if_none_match] == file.etag) {
    Response response{http::status::not_modified, request.version()};
    response.set(http::field::server, kServerName);
    response.set(http::field::etag, file.etag);
    response.keep_alive(request.keep_alive());
    return response;
  }
  Response response{http::status::ok, request.version()};
  response.set(http::field::server, kServerName);
  response.set(http::field::content_type, std::string(file.content_type));
  response.set(http::field::etag, file.etag);
  response.set(http::field::cache_control, "no-cache");  // revalidate: cheap with the ETag
  response.keep_alive(request.keep_alive());
  if (request.method() == http::verb::head) {
    response.content_length(file.body.size());
  } else {
    response.body() = std::string(file.body);
    response.prepare_payload();
  }
  return response;
}

constexpr std::string_view kSpeechData = "/speech/data/";

// The server's espeak-ng voice data (speech_data.hpp), read from its folder
// at each request: the files are at most a few hundred kilobytes, and a
// browser fetches them once, when read aloud is first turned on.
Response speech_data_response(const Request& request, std::string_view path) {
  const std::string_view name = path.substr(kSpeechData.size());
  const auto file = served_speech_data().find(name);
  std::ifstream in;
  if (file) in.open(*file, std::ios::binary);
  if (!in.is_open()) return text_response(http::status::not_found, request.version(), request.keep_alive(),
                                SpeechData::refusal(name) + "\n");
  const std::string body{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return file_response(request, static_file("application/octet-stream", body));
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

  const std::string_view path = target.substr(0, target.find('?'));
  if (path.starts_with(kSpeechData)) return speech_data_response(request, path);

  const auto file = find_static_file(target);
  if (!file)
    return text_response(http::status::not_found, request.version(), request.keep_alive(),
                         "nothing at " + std::string(target) + "\n");
  return file_response(request, *file);
}

}  // namespace fw::server
