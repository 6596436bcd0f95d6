#pragma once
// One HTTP/1.1 connection: reads requests within the limits, answers them
// (static content, the API, uploads) and keeps the connection alive while
// the peer wants; hands the connection, and its ConnectionTicket, to a
// WebSocketSession on an upgrade. A request's header must arrive within
// limits::kHeaderTimeout, however slowly its bytes come. Behind a trusted
// proxy (--trusted-proxy), each request's forwarding header names the
// client that its limits, log lines and room joins see.
#include <memory>
#include <optional>

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "connection_admission.hpp"
#include "metrics.hpp"
#include "server_config.hpp"
#include "upload_pace.hpp"
#include "upload_reservation.hpp"

namespace fw::server {

class PhotoPreparation;
struct ApiServices;
struct SessionServices;

/// What an HTTP connection uses of the server, made once with the
/// listeners (network_server.cpp); each session keeps a copy of these
/// references.
struct HttpServices {
  const ServerConfig& config;  ///< body limits, upload pace, trusted proxies
  Metrics& metrics;            ///< HTTP connections open
  AbuseLog& abuse;             ///< refusals by kind, for the log and /metrics
  AddressLimits& addresses;    ///< connections per forwarded client
  PhotoPreparation& photos;    ///< takes the uploads
  const ApiServices& api;      ///< answers the API's requests (rest_api.hpp)
  const SessionServices& sessions;  ///< what an upgraded connection's session is made with
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  /// `ticket` counts the connection until it closes (or, upgraded, until
  /// the WebSocket closes).
  HttpSession(const HttpServices& services, boost::asio::ip::tcp::socket&& socket, ConnectionTicket ticket);
  ~HttpSession();
  void run();

 private:
  void do_read();
  /// The header of a request whose first bytes (if any) are in buffer_.
  void read_header();
  void on_header(boost::beast::error_code ec, std::size_t bytes);
  void on_read(boost::beast::error_code ec, std::size_t bytes);
  /// An upload's body, read piece by piece: each piece counted against the
  /// address's and the server's bytes in flight as it arrives, and the
  /// body held to its pace (UploadPace, --min-upload-bytes-per-second).
  void start_upload_body();
  void read_upload_bytes();
  void on_upload_bytes(boost::beast::error_code ec, std::size_t bytes);
  /// The pace timer: the body missed its pace with nothing more arriving.
  void on_pace_deadline();
  /// 408 to a body that came slower than the pace; counted.
  void refuse_slow_upload();
  bool answer_read_error(boost::beast::error_code ec);
  /// From a trusted proxy: takes the client the request's header names as
  /// the peer, and counts the connection against it; false when that
  /// address holds its share of connections (the refusal is on its way).
  bool take_forwarded_client();
  /// Counts and logs (AbuseLog) a 4xx answer that says the peer erred.
  void note_bad_request(unsigned status, const std::string& what);
  /// The same for an answer to a whole request (404, 405...).
  void note_if_refused(const boost::beast::http::response<boost::beast::http::string_body>& response,
                       const boost::beast::http::request<boost::beast::http::string_body>& request);
  void send(boost::beast::http::response<boost::beast::http::string_body>&& response);
  void on_write(bool close, boost::beast::error_code ec, std::size_t bytes);
  void do_close();
  void linger();

  const HttpServices services_;
  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::string_body>> parser_;
  std::shared_ptr<void> response_;  // kept alive until its write completes
  ConnectionTicket ticket_;
  /// The TCP peer, and whether it is a trusted proxy.
  boost::asio::ip::address socket_peer_;
  bool via_proxy_ = false;
  /// Whom limits and log lines count: the TCP peer, or the client a trusted
  /// proxy forwards for the request under way.
  std::string peer_address_;
  /// What the connection waits for: the next request (a keep-alive idle),
  /// a header (under its deadline), or a body.
  enum class Reading { idle, header, body } reading_ = Reading::header;
  bool first_request_ = true;
  bool upload_ = false;
  /// The bytes of the upload being received or prepared (PhotoPreparation::admit).
  UploadReservation upload_bytes_;
  /// The pace its body must keep, and the timer that fires when it misses
  /// the pace without a byte arriving (a read waits meanwhile).
  std::optional<UploadPace> upload_pace_;
  boost::asio::steady_timer pace_timer_;
  bool pace_missed_ = false;
  std::size_t lingered_bytes_ = 0;
};

}  // namespace fw::server
