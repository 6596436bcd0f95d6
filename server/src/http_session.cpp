#include "http_session.hpp"

#include <boost/asio/dispatch.hpp>
#include <spdlog/spdlog.h>

#include "http_responses.hpp"
#include "server_limits.hpp"

namespace fw::server {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

HttpSession::HttpSession(net::ip::tcp::socket&& socket, std::shared_ptr<std::atomic<std::size_t>> open_connections)
    : stream_(std::move(socket)), buffer_(limits::kMaxHeaderBytes + limits::kMaxBodyBytes),
      open_connections_(std::move(open_connections)) {}

HttpSession::~HttpSession() { --*open_connections_; }

void HttpSession::run() {
  // Sessions run on their own strand (the socket was accepted onto one).
  net::dispatch(stream_.get_executor(), beast::bind_front_handler(&HttpSession::do_read, shared_from_this()));
}

void HttpSession::do_read() {
  parser_.emplace();
  parser_->header_limit(limits::kMaxHeaderBytes);
  parser_->body_limit(limits::kMaxBodyBytes);
  // A keep-alive connection may idle a while; a started request must finish soon.
  stream_.expires_after(first_request_ ? limits::kRequestTimeout : limits::kIdleTimeout);
  first_request_ = false;
  http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
  if (ec == http::error::end_of_stream || ec == beast::error::timeout || ec == net::error::operation_aborted)
    return do_close();
  if (ec == http::error::header_limit)
    return send(error_response(http::status::request_header_fields_too_large, 11,
                               "request headers exceed 8 KiB; send fewer or shorter headers"));
  if (ec == http::error::body_limit)
    return send(error_response(http::status::payload_too_large, 11, "request body exceeds 64 KiB"));
  if (ec) {
    if (ec == net::error::connection_reset || ec == net::error::eof) return do_close();
    return send(error_response(http::status::bad_request, 11, "malformed HTTP request: " + ec.message()));
  }
  send(respond_to(parser_->release()));
}

void HttpSession::send(http::response<http::string_body>&& response) {
  auto shared = std::make_shared<http::response<http::string_body>>(std::move(response));
  response_ = shared;
  const bool close = shared->need_eof();
  stream_.expires_after(limits::kRequestTimeout);
  http::async_write(stream_, *shared,
                    beast::bind_front_handler(&HttpSession::on_write, shared_from_this(), close));
}

void HttpSession::on_write(bool close, beast::error_code ec, std::size_t) {
  response_.reset();
  if (ec) {
    if (ec != beast::error::timeout && ec != net::error::broken_pipe && ec != net::error::connection_reset)
      spdlog::debug("http write: {}", ec.message());
    return do_close();
  }
  if (close) return do_close();
  do_read();
}

void HttpSession::do_close() {
  beast::error_code ec;
  stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ec);
}

}  // namespace fw::server
