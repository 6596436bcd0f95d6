#include "http_session.hpp"

#include <algorithm>

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/websocket.hpp>
#include <spdlog/spdlog.h>

#include "api_access.hpp"
#include "connection_refusal.hpp"
#include "http_responses.hpp"
#include "log_text.hpp"
#include "look_api.hpp"
#include "peer_address.hpp"
#include "photo_preparation.hpp"
#include "rest_api.hpp"
#include "server_limits.hpp"
#include "trusted_proxies.hpp"
#include "websocket_session.hpp"

namespace fw::server {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace {

/// The request's target as a log line may show it.
std::string loggable_target(const Request& request) {
  return printable({request.target().data(), request.target().size()}, 80);
}

/// Every line of the headers a proxy names the client in.
ForwardingHeaders forwarding_headers(const http::fields& fields) {
  ForwardingHeaders headers;
  const auto add_lines = [&fields](const char* name, std::vector<std::string_view>& lines) {
    const auto [first, last] = fields.equal_range(name);
    for (auto field = first; field != last; ++field) lines.emplace_back(field->value().data(), field->value().size());
  };
  add_lines("X-Forwarded-For", headers.x_forwarded_for);
  add_lines("Forwarded", headers.forwarded);
  return headers;
}

}  // namespace

HttpSession::HttpSession(const HttpServices& services, net::ip::tcp::socket&& socket, ConnectionTicket ticket)
    : services_(services), stream_(std::move(socket)),
      buffer_(limits::kMaxHeaderBytes + limits::kMaxBodyBytes), ticket_(std::move(ticket)),
      pace_timer_(stream_.get_executor()) {
  beast::error_code ec;
  socket_peer_ = stream_.socket().remote_endpoint(ec).address();
  via_proxy_ = services_.config.trusted_proxies.contains(socket_peer_);
  peer_address_ = socket_peer_.to_string();
  services_.metrics.http_connections.fetch_add(1);
}

HttpSession::~HttpSession() { services_.metrics.http_connections.fetch_sub(1); }

void HttpSession::run() {
  // When the port is full, a connection still waiting for a whole header
  // gives its place up (ConnectionShares): its socket closes, the read
  // under way ends, and the session with it.
  ticket_.on_evict([weak = weak_from_this(), executor = stream_.get_executor()] {
    net::post(executor, [weak] {
      if (auto self = weak.lock()) {
        beast::error_code ignored;
        self->stream_.socket().close(ignored);
      }
    });
  });
  // Sessions run on their own strand (the socket was accepted onto one).
  net::dispatch(stream_.get_executor(), beast::bind_front_handler(&HttpSession::do_read, shared_from_this()));
}

void HttpSession::do_read() {
  parser_.emplace();
  parser_->header_limit(limits::kMaxHeaderBytes);
  // The body's limit depends on the target: the header is read under the
  // larger one (Beast checks Content-Length while parsing it), on_header
  // then holds other requests to theirs.
  parser_->body_limit(std::max<std::uint64_t>(limits::kMaxBodyBytes, services_.config.max_upload_bytes));
  if (via_proxy_) {
    // A proxy's connection between requests is nobody's: the next request
    // may be another client's (a proxy reuses its connections to us).
    ticket_.release_address();
    peer_address_ = socket_peer_.to_string();
  }
  if (first_request_ || buffer_.size() > 0) return read_header();
  // A keep-alive connection may idle a while before its next request; the
  // header's deadline starts with the request's first byte.
  reading_ = Reading::idle;
  stream_.expires_after(limits::kIdleTimeout);
  ticket_.waiting(std::chrono::steady_clock::now() + limits::kIdleTimeout);
  stream_.async_read_some(buffer_.prepare(limits::kMaxHeaderBytes),
                          [self = shared_from_this()](beast::error_code ec, std::size_t bytes) {
                            if (self->answer_read_error(ec)) return;
                            self->buffer_.commit(bytes);
                            self->read_header();
                          });
}

void HttpSession::read_header() {
  // The first request's header counts from accept: a connection that sends
  // nothing, or dribbles its header a byte at a time, holds its place (and
  // the address's share) for this long at most. Set once, not per read.
  reading_ = Reading::header;
  stream_.expires_after(limits::kHeaderTimeout);
  ticket_.waiting(std::chrono::steady_clock::now() + limits::kHeaderTimeout);
  first_request_ = false;
  // The header first: an upload may be larger than other requests' bodies.
  http::async_read_header(stream_, buffer_, *parser_,
                          beast::bind_front_handler(&HttpSession::on_header, shared_from_this()));
}

void HttpSession::note_bad_request(unsigned status, const std::string& what) {
  services_.abuse.note(Abuse::http_bad_request, peer_address_, std::to_string(status) + ": " + what);
}

bool HttpSession::answer_read_error(beast::error_code ec) {
  if (ec == http::error::end_of_stream || ec == beast::error::timeout || ec == net::error::operation_aborted ||
      ec == net::error::connection_reset || ec == net::error::eof) {
    // The peer left or went quiet: nothing to linger for. Quiet past a
    // deadline while a request was under way is a slow request (slowloris).
    if (ec == beast::error::timeout && reading_ != Reading::idle)
      services_.abuse.note(Abuse::handshake_timeout, peer_address_,
                          reading_ == Reading::header ? "no whole request header within " +
                                                            std::to_string(limits::kHeaderTimeout.count()) + " s"
                                                      : std::string("the request body did not arrive in time"));
    beast::error_code ignored;
    stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
    return true;
  }
  if (ec == http::error::header_limit) {
    note_bad_request(431, "request headers over 8 KiB");
    send(error_response(http::status::request_header_fields_too_large, 11,
                        "request headers exceed 8 KiB; send fewer or shorter headers"));
    return true;
  }
  if (ec == http::error::body_limit) {
    // Beast may refuse while still parsing the header, before the target is
    // known here: the message covers both kinds of request.
    note_bad_request(413, "request body too large");
    send(error_response(http::status::payload_too_large, 11,
                        "the request body is too large: uploads (POST /api/avatars) take at most " +
                            std::to_string(services_.config.max_upload_bytes / 1024) +
                            " KiB, so send a smaller photo (about 30 KB is plenty); other requests 64 KiB"));
    return true;
  }
  if (ec) {
    note_bad_request(400, "malformed HTTP request: " + ec.message());
    send(error_response(http::status::bad_request, 11, "malformed HTTP request: " + ec.message()));
    return true;
  }
  return false;
}

bool HttpSession::take_forwarded_client() {
  if (!via_proxy_) return true;
  const ClientAddress client =
      client_address(services_.config.trusted_proxies, socket_peer_, forwarding_headers(parser_->get()));
  peer_address_ = client.address.to_string();
  if (client.source == ClientAddress::Source::malformed)
    services_.abuse.note(Abuse::bad_forwarded_header, peer_address_,
                        "from a trusted proxy: " + client.problem + "; counted as the proxy's own request");
  if (ticket_.count_against(services_.addresses, address_key(client.address))) return true;
  const std::size_t per_address = services_.addresses.limits().connections_per_address;
  services_.abuse.note(Abuse::address_connection_limit, peer_address_,
                      "request through a proxy refused: the address holds " + std::to_string(per_address) +
                          " connections already");
  Response refusal = error_response(http::status::too_many_requests, parser_->get().version(),
                                    refusal_reason(Abuse::address_connection_limit, per_address,
                                                   std::chrono::seconds(10)));
  refusal.set(http::field::retry_after, "10");
  send(std::move(refusal));
  return false;
}

void HttpSession::on_header(beast::error_code ec, std::size_t) {
  if (answer_read_error(ec)) return;
  // A whole header: the connection carries a request, and keeps its place.
  ticket_.busy(std::chrono::steady_clock::now() + limits::kRequestTimeout);
  if (!take_forwarded_client()) return;
  const auto& header = parser_->get();
  const std::string_view target(header.target().data(), header.target().size());
  upload_ = header.method() == http::verb::post && target.substr(0, target.find('?')) == "/api/avatars";
  if (upload_) {
    // With --auth-secret, only who holds an invitation may upload (the
    // browser sends the invite link's token).
    Response refusal;
    if (!api_access(services_.config, header, refusal)) {
      services_.abuse.note(Abuse::unauthorized, peer_address_, "an upload without a valid token");
      return send(std::move(refusal));
    }
  }
  // A look's script is refused by its declared size, before its body is read.
  const bool look_save = is_look_save(header.method(), target);
  const std::size_t limit =
      upload_ ? services_.config.max_upload_bytes : look_save ? kMaxLookScriptBytes : limits::kMaxBodyBytes;
  if (parser_->content_length() && *parser_->content_length() > limit) {
    if (!look_save) return (void)answer_read_error(http::error::body_limit);
    note_bad_request(413, "a saved look's script over " + std::to_string(limit) + " bytes");
    return send(oversized_look(header.version(), *parser_->content_length()));
  }
  parser_->body_limit(limit);  // for chunked bodies
  // An upload is admitted or refused before its body is read (a refused
  // body is drained by the lingering close): its address's rate, whether
  // the bytes it declares (or the largest upload when chunked) would fit
  // in memory beside what is in flight, and the photo queue.
  if (upload_)
    if (auto refusal = services_.photos.admit(header.version(), parser_->content_length().value_or(limit),
                                              peer_address_, upload_bytes_))
      return send(std::move(*refusal));
  reading_ = Reading::body;
  if (upload_) return start_upload_body();
  stream_.expires_after(limits::kRequestTimeout);
  http::async_read(stream_, buffer_, *parser_, beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

void HttpSession::start_upload_body() {
  // An empty body (Content-Length: 0) is whole with its header: nothing to
  // wait for, and a read would wait for bytes that never come.
  if (parser_->is_done()) return on_read({}, 0);
  const std::size_t pace = services_.config.min_upload_bytes_per_second;
  upload_pace_.emplace(pace, limits::kUploadPaceWindow, UploadPace::Clock::now());
  pace_missed_ = false;
  // The pace decides; the deadline is only a backstop, past what a body of
  // the largest upload that keeps the pace takes. Without a pace, a body
  // has the fixed time it always had.
  if (pace == 0) {
    stream_.expires_after(limits::kUploadTimeout);
  } else {
    const auto longest = std::chrono::seconds(services_.config.max_upload_bytes / pace + 1);
    stream_.expires_after(2 * limits::kUploadPaceWindow + longest);
  }
  read_upload_bytes();
}

void HttpSession::read_upload_bytes() {
  const auto deadline = upload_pace_->deadline();
  if (deadline != UploadPace::Clock::time_point::max()) {
    pace_timer_.expires_at(deadline);  // cancels the wait for the deadline before
    pace_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (!ec) self->on_pace_deadline();
    });
  }
  http::async_read_some(stream_, buffer_, *parser_,
                        beast::bind_front_handler(&HttpSession::on_upload_bytes, shared_from_this()));
}

void HttpSession::on_pace_deadline() {
  if (!upload_pace_ || !upload_pace_->too_slow(UploadPace::Clock::now())) return;  // bytes came meanwhile
  // The read under way completes (operation_aborted) and answers.
  pace_missed_ = true;
  stream_.cancel();
}

void HttpSession::on_upload_bytes(beast::error_code ec, std::size_t) {
  const auto now = UploadPace::Clock::now();
  if (!ec) {
    // Counted as received, not as declared: a body that is promised and
    // dribbled holds what it sent, so that it cannot crowd others out.
    const std::size_t received = parser_->get().body().size();
    const UploadShare share = upload_bytes_.grow(received - std::min(received, upload_bytes_.bytes()));
    if (share != UploadShare::granted) {
      pace_timer_.cancel();
      upload_bytes_.release();
      return send(services_.photos.share_refusal(share, parser_->get().version(), received, peer_address_));
    }
    upload_pace_->record(now, received);
    // Bytes that came as the pace timer fired still count: a body they
    // complete, or bring back to its pace, goes on.
    pace_missed_ = false;
    if (parser_->is_done()) {
      pace_timer_.cancel();
      return on_read(ec, 0);
    }
    if (upload_pace_->too_slow(now)) return refuse_slow_upload();
    return read_upload_bytes();
  }
  if (pace_missed_) return refuse_slow_upload();  // the read was cancelled for it
  pace_timer_.cancel();
  on_read(ec, 0);
}

void HttpSession::refuse_slow_upload() {
  pace_timer_.cancel();
  upload_bytes_.release();
  const std::size_t pace = services_.config.min_upload_bytes_per_second;
  const auto window = limits::kUploadPaceWindow.count();
  services_.abuse.note(Abuse::upload_too_slow, peer_address_,
                      "an upload's body came slower than " + std::to_string(pace) + " bytes a second over " +
                          std::to_string(window) + " s, after " +
                          std::to_string(parser_->get().body().size()) + " bytes");
  send(error_response(http::status::request_timeout, parser_->get().version(),
                      "the upload came too slowly: once it has started, the server needs at least " +
                          std::to_string((pace + 1023) / 1024) + " KiB a second (over each " +
                          std::to_string(window) + " s) and received " +
                          std::to_string(parser_->get().body().size()) +
                          " bytes in all; upload again from a better connection, or send a smaller photo"));
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
  if (ec) upload_bytes_.release();  // an upload's body that failed to come holds nothing
  if (answer_read_error(ec)) return;
  Request request = parser_->release();
  if (beast::websocket::is_upgrade(request)) {
    if (request.target() != "/" && request.target() != "/ws") {
      note_bad_request(404, "a WebSocket upgrade to " + loggable_target(request));
      return send(error_response(http::status::not_found, request.version(), "the room protocol is at /ws"));
    }
    auto session =
        std::make_shared<WebSocketSession>(services_.sessions, std::move(stream_), peer_address_, std::move(ticket_));
    session->run(std::move(request));
    return;  // this HttpSession ends here; the connection lives on in the WebSocket session
  }
  if (upload_) {
    auto self = shared_from_this();
    services_.photos.upload(std::move(request), peer_address_, [self](Response response) {
      net::post(self->stream_.get_executor(), [self, response = std::move(response)]() mutable {
        self->upload_bytes_.release();  // answered: its body is no longer held
        self->send(std::move(response));
      });
    });
    return;
  }
  if (is_look_route(std::string_view(request.target().data(), request.target().size()))) {
    // Off the loop: the look store may wait for the disk or Redis.
    auto self = shared_from_this();
    net::post(services_.api.workers, [self, request = std::move(request)]() mutable {
      Response response = *respond_to_looks(self->services_.api, request, self->peer_address_);
      net::post(self->stream_.get_executor(),
                [self, request = std::move(request), response = std::move(response)]() mutable {
                  self->note_if_refused(response, request);
                  self->send(std::move(response));
                });
    });
    return;
  }
  std::optional<Response> response;
  if (request.method() == http::verb::get || request.method() == http::verb::head ||
      request.method() == http::verb::delete_)
    response = respond_to_api(services_.api, request);
  if (!response) response = respond_to(request);
  note_if_refused(*response, request);
  send(std::move(*response));
}

void HttpSession::note_if_refused(const Response& response, const Request& request) {
  const unsigned status = response.result_int();
  // 401, 403 and 429 are counted where they are decided (unauthorized, rate limits).
  if (status < 400 || status >= 500 || status == 401 || status == 403 || status == 429) return;
  note_bad_request(status, std::string(request.method_string()) + " " + loggable_target(request));
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
  // A lingering close (limits::kLingerTimeout): the session lives on while
  // it reads what the peer still sends, until the peer closes too.
  stream_.expires_after(limits::kLingerTimeout);
  linger();
}

void HttpSession::linger() {
  // The parse buffer is done with; reuse it rather than allocate.
  buffer_.clear();
  stream_.async_read_some(buffer_.prepare(16 * 1024), [self = shared_from_this()](beast::error_code ec, std::size_t n) {
    self->lingered_bytes_ += n;
    // Bounded in bytes as well as in time: a photo straight from a camera
    // may be several times the upload limit.
    if (ec || self->lingered_bytes_ > limits::kMaxLingerBytes) return;
    self->linger();
  });
}

}  // namespace fw::server
