#include "avatar_upload.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

namespace fw::client {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;

using Request = http::request<http::vector_body<std::uint8_t>>;
using Response = http::response<http::string_body>;

Request upload_request(const UploadTarget& target, const std::string& content_type,
                       std::span<const std::uint8_t> body) {
  Request request{http::verb::post, "/api/avatars", 11};
  request.set(http::field::host, target.host + ":" + target.port);
  request.set(http::field::user_agent, "facewire-client");
  request.set(http::field::content_type, content_type);
  if (!target.token.empty()) request.set(http::field::authorization, "Bearer " + target.token);
  request.body().assign(body.begin(), body.end());
  request.prepare_payload();
  return request;
}

// Connects, sends the request and reads the answer, all within one deadline
// (beast's timeouts are per operation; these run one after the other, so
// each gets what is left).
boost::system::error_code exchange(const UploadTarget& target, const Request& request, int timeout_s,
                                   Response& response) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  boost::system::error_code ec;
  asio::ip::tcp::resolver resolver(io);
  const auto addresses = resolver.resolve(target.host, target.port, ec);
  if (ec) return ec;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  stream.expires_at(deadline);
  stream.connect(addresses, ec);
  http::response_parser<http::string_body> parser;
  parser.body_limit(64 * 1024);
  beast::flat_buffer buffer;
  // beast::tcp_stream's synchronous calls do not honour its timer; run them
  // as async operations on this io_context so the deadline holds.
  if (!ec) {
    http::async_write(stream, request, [&](boost::system::error_code e, std::size_t) { ec = e; });
    io.run();
    io.restart();
  }
  if (!ec) {
    stream.expires_at(deadline);
    http::async_read(stream, buffer, parser, [&](boost::system::error_code e, std::size_t) { ec = e; });
    io.run();
  }
  if (!ec) response = parser.release();
  return ec;
}

// The server's answer: 201 (or 200) with {"asset": ID, "key": KEY}, else its explanation.
bool read_answer(const Response& response, UploadAnswer& answer, std::string& error) {
  if (response.result() != http::status::created && response.result() != http::status::ok) {
    error = "the server refused the avatar (" + std::to_string(response.result_int()) + "): " + response.body();
    return false;
  }
  const auto json = nlohmann::json::parse(response.body(), nullptr, false);
  if (!json.is_object() || !json.contains("asset") || !json["asset"].is_string() ||
      json["asset"].get<std::string>().empty()) {
    error = "the server's answer to the upload has no asset id: " + response.body().substr(0, 200);
    return false;
  }
  answer.asset = json["asset"].get<std::string>();
  if (!json.contains("key") || !json["key"].is_string()) {
    error = "the server's answer to the upload has no key (is it an older server?): " + response.body().substr(0, 200);
    return false;
  }
  answer.key = json["key"].get<std::string>();
  return true;
}

}  // namespace

bool upload_avatar(const UploadTarget& target, const std::string& content_type, std::span<const std::uint8_t> body,
                   int timeout_s, UploadAnswer& answer, std::string& error) {
  const std::string where = "http://" + target.host + ":" + target.port + "/api/avatars";
  Response response;
  const boost::system::error_code ec = exchange(target, upload_request(target, content_type, body), timeout_s, response);
  if (ec) {
    error = "uploading the avatar to " + where + ": " +
            (ec == beast::error::timeout ? "no answer within " + std::to_string(timeout_s) + " s" : ec.message());
    return false;
  }
  return read_answer(response, answer, error);
}

}  // namespace fw::client
