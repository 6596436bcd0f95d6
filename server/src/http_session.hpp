#pragma once
// One HTTP/1.1 connection: reads requests within the limits, answers them
// (static content, the API, uploads) and keeps the connection alive while
// the peer wants; hands the connection to a WebSocketSession on an upgrade.
#include <atomic>
#include <memory>
#include <optional>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include "server_context.hpp"

namespace fw::server {

class PhotoPreparation;

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  /// `open_connections` counts live sessions (the listener's limit);
  /// `photos` takes the uploads.
  HttpSession(ServerContext& context, PhotoPreparation& photos, boost::asio::ip::tcp::socket&& socket,
              std::shared_ptr<std::atomic<std::size_t>> open_connections);
  ~HttpSession();
  void run();

 private:
  void do_read();
  void on_header(boost::beast::error_code ec, std::size_t bytes);
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  bool answer_read_error(boost::beast::error_code ec);
  void send(boost::beast::http::response<boost::beast::http::string_body>&& response);
  void on_write(bool close, boost::beast::error_code ec, std::size_t bytes);
  void do_close();
  void linger();

  ServerContext& context_;
  PhotoPreparation& photos_;
  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::shared_ptr<void> response_;  // kept alive until its write completes
  std::shared_ptr<std::atomic<std::size_t>> open_connections_;
  std::string peer_address_;
  bool first_request_ = true;
  bool upload_ = false;
  std::size_t lingered_bytes_ = 0;
};

}  // namespace fw::server
