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

// Resolves, connects, sends the request and reads the answer, all within
// one deadline (beast's timeouts are per operation; these run one after the
// other, so each gets what is left). Handlers keep the exchange alive.
class UploadExchange : public std::enable_shared_from_this<UploadExchange> {
 public:
  using Done = std::function<void(boost::system::error_code, Response)>;

  UploadExchange(asio::io_context& io, Request request, Done done)
      : resolver_(io), stream_(io), request_(std::move(request)), done_(std::move(done)) {
    parser_.body_limit(64 * 1024);
  }

  void start(const UploadTarget& target, int timeout_s) {
    deadline_ = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
    resolver_.async_resolve(target.host, target.port,
                            [self = shared_from_this()](boost::system::error_code ec, auto addresses) {
                              if (ec) return self->finish(ec);
                              self->stream_.expires_at(self->deadline_);
                              self->stream_.async_connect(addresses, [self](boost::system::error_code e, const auto&) {
                                self->on_connected(e);
                              });
                            });
  }

 private:
  void on_connected(boost::system::error_code ec) {
    if (ec) return finish(ec);
    stream_.expires_at(deadline_);
    http::async_write(stream_, request_, [self = shared_from_this()](boost::system::error_code e, std::size_t) {
      self->on_written(e);
    });
  }

  void on_written(boost::system::error_code ec) {
    if (ec) return finish(ec);
    stream_.expires_at(deadline_);
    http::async_read(stream_, buffer_, parser_, [self = shared_from_this()](boost::system::error_code e, std::size_t) {
      self->finish(e);
    });
  }

  void finish(boost::system::error_code ec) {
    boost::system::error_code ignored;
    stream_.socket().close(ignored);
    done_(ec, ec ? Response{} : parser_.release());
  }

  asio::ip::tcp::resolver resolver_;
  beast::tcp_stream stream_;
  Request request_;
  http::response_parser<http::string_body> parser_;
  beast::flat_buffer buffer_;
  std::chrono::steady_clock::time_point deadline_;
  Done done_;
};

// The server's answer: 201 (or 200) with {"asset": ID, "key": KEY}, else its explanation.
bool read_answer(const Response& response, UploadAnswer& answer, std::string& error) {
  answer.http_status = static_cast<int>(response.result_int());
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

void async_upload_avatar(asio::io_context& io, const UploadTarget& target, const std::string& content_type,
                         std::shared_ptr<const std::vector<std::uint8_t>> body, int timeout_s,
                         std::function<void(bool ok, const UploadAnswer& answer, const std::string& error)> done) {
  const std::string where = "http://" + target.host + ":" + target.port + "/api/avatars";
  auto exchange = std::make_shared<UploadExchange>(
      io, upload_request(target, content_type, *body),
      [where, timeout_s, done = std::move(done)](boost::system::error_code ec, const Response& response) {
        UploadAnswer answer;
        std::string error;
        if (ec) {
          error = "uploading the avatar to " + where + ": " +
                  (ec == beast::error::timeout ? "no answer within " + std::to_string(timeout_s) + " s" : ec.message());
          return done(false, answer, error);
        }
        const bool ok = read_answer(response, answer, error);
        done(ok, answer, error);
      });
  exchange->start(target, timeout_s);
}

bool upload_avatar(const UploadTarget& target, const std::string& content_type, std::span<const std::uint8_t> body,
                   int timeout_s, UploadAnswer& answer, std::string& error) {
  asio::io_context io;
  bool ok = false;
  async_upload_avatar(io, target, content_type, std::make_shared<const std::vector<std::uint8_t>>(body.begin(), body.end()),
                      timeout_s, [&](bool done_ok, const UploadAnswer& done_answer, const std::string& done_error) {
                        ok = done_ok;
                        answer = done_answer;
                        error = done_error;
                      });
  io.run();
  return ok;
}

}  // namespace fw::client
