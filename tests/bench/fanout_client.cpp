#include "fanout_client.hpp"

#include <chrono>

#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>

#include "fw/codec/messages.hpp"

namespace fw::bench::fanout {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

void Totals::note_close(const std::string& why) {
  const std::lock_guard lock(reasons_mutex_);
  ++reasons_[why];
}

std::map<std::string, int> Totals::close_reasons() const {
  const std::lock_guard lock(reasons_mutex_);
  return reasons_;
}

std::uint64_t steady_now_us() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

BenchClient::BenchClient(asio::io_context& io, Totals& totals, std::string room, std::string name)
    : ws_(asio::make_strand(io)), ping_timer_(ws_.get_executor()), totals_(totals), room_(std::move(room)),
      name_(std::move(name)) {}

void BenchClient::start(const tcp::endpoint& server) {
  beast::get_lowest_layer(ws_).expires_after(std::chrono::seconds(30));
  beast::get_lowest_layer(ws_).async_connect(server, [self = shared_from_this()](beast::error_code ec) {
    if (ec) return self->close("connect: " + ec.message());
    beast::get_lowest_layer(self->ws_).expires_never();
    self->ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::client));
    self->ws_.read_message_max(codec::kMaxDownstreamMessageBytes);
    self->ws_.binary(true);
    self->ws_.async_handshake("127.0.0.1", "/", [self](beast::error_code handshake_ec) {
      if (handshake_ec) return self->close("handshake: " + handshake_ec.message());
      codec::Hello hello;
      hello.room = self->room_;
      hello.name = self->name_;
      hello.timestamps = true;
      hello.no_packages = true;
      self->send(hello);
      self->read();
      self->ping();
    });
  });
}

double BenchClient::tick_hz() const {
  if (last_tick_time_us_ <= first_tick_time_us_) return 0;
  return static_cast<double>(last_tick_ - first_tick_) * 1e6 / static_cast<double>(last_tick_time_us_ - first_tick_time_us_);
}

template <class Message>
void BenchClient::send(const Message& message) {
  auto bytes = std::make_shared<std::vector<std::uint8_t>>();
  codec::write_message(message, *bytes);
  send_bytes(bytes);
}

void BenchClient::send_bytes(std::shared_ptr<std::vector<std::uint8_t>> bytes) {
  // Upstream messages are rare (hello, a ping every 15 s, resyncs): one at
  // a time is enough; a message offered while one is in flight waits.
  outbox_.push_back(std::move(bytes));
  if (outbox_.size() == 1) write_next();
}

void BenchClient::write_next() {
  if (outbox_.empty() || closed_) return;
  ws_.async_write(asio::buffer(*outbox_.front()), [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if (ec) return self->close("write: " + ec.message());
    self->outbox_.erase(self->outbox_.begin());
    self->write_next();
  });
}

void BenchClient::ping() {
  ping_timer_.expires_after(std::chrono::seconds(15));
  ping_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
    if (ec || self->closed_) return;
    self->send(codec::Ping{++self->pings_, steady_now_us()});
    self->ping();
  });
}

void BenchClient::read() {
  buffer_.clear();
  ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, std::size_t n) {
    if (ec == websocket::error::closed)
      return self->close("server closed: " + std::string(self->ws_.reason().reason.c_str()));
    if (ec) return self->close("read: " + ec.message());
    const auto data = self->buffer_.cdata();
    self->on_message({static_cast<const std::uint8_t*>(data.data()), data.size()}, n);
    self->read();
  });
}

void BenchClient::on_message(std::span<const std::uint8_t> message, std::size_t n) {
  const bool measuring = totals_.measuring.load(std::memory_order_relaxed);
  if (measuring) totals_.bytes += n;
  switch (codec::classify(message)) {
    case codec::MessageKind::stream_header: {
      codec::StreamOptions options;
      if (codec::read_stream_header(message, options) == codec::DecodeError::ok) decoder_ = codec::RoomDecoder(options);
      return;
    }
    case codec::MessageKind::session:
      break;
    default:
      return;
  }
  switch (codec::session_type(message)) {
    case codec::MessageType::welcome:
      ++totals_.joined;
      return;
    case codec::MessageType::closing: {
      codec::Closing closing;
      if (codec::read_message(message, closing) != codec::MessageError::ok) return close("an unreadable closing message");
      return close("server: " + closing.reason);
    }
    case codec::MessageType::timed_room_frame: {
      codec::TimedRoomFrame timed;
      if (codec::read_message(message, timed) != codec::MessageError::ok) return;
      const auto result = decoder_.decode(timed.room_frame);
      const std::uint64_t decoded_us = steady_now_us();
      if (!measuring) return;
      ++totals_.room_frames;
      for (const auto& [id, error] : result.avatars) {
        if (error == codec::DecodeError::ok) ++totals_.avatar_frames;
        else ++totals_.decode_errors;
      }
      if (samples_.size() < kMaxSamples && decoded_us >= timed.server_time_us)
        samples_.push_back({timed.tick, timed.server_time_us, decoded_us});
      if (first_tick_time_us_ == 0) {
        first_tick_ = timed.tick;
        first_tick_time_us_ = timed.server_time_us;
      }
      last_tick_ = timed.tick;
      last_tick_time_us_ = timed.server_time_us;
      const auto needed = decoder_.needing_key_frames();
      if (!needed.empty() && !resync_sent_) {
        resync_sent_ = true;  // once: the server answers with key frames
        auto bytes = std::make_shared<std::vector<std::uint8_t>>();
        codec::write_resync_request(needed, *bytes);
        send_bytes(bytes);
      }
      return;
    }
    default:
      return;
  }
}

void BenchClient::close(const std::string& why) {
  if (closed_) return;
  closed_ = true;
  ++totals_.closed;
  totals_.note_close(why);
  ping_timer_.cancel();
  beast::error_code ignored;
  beast::get_lowest_layer(ws_).socket().close(ignored);
}

}  // namespace fw::bench::fanout
