#include "in_memory_transport.hpp"

#include <deque>
#include <utility>

#include <boost/asio/error.hpp>
#include <boost/asio/post.hpp>

namespace fw::client {

namespace asio = boost::asio;

// What both ends of one in-memory connection share: the messages on their
// way each direction, and how (whether) the connection ended.
class InMemoryConnection : public std::enable_shared_from_this<InMemoryConnection> {
 public:
  InMemoryConnection(asio::io_context& io, boost::system::error_code refusal) : io_(io), refusal_(refusal) {}

  void connect(MessageTransport::Done done) {
    asio::post(io_, [self = shared_from_this(), done = std::move(done)] {
      if (!self->refusal_ && !self->ended()) self->connected_ = true;
      done(self->refusal_ ? self->refusal_ : self->ended() ? asio::error::operation_aborted : boost::system::error_code{});
    });
  }

  void read(MessageTransport::Received received) {
    pending_read_ = std::move(received);
    serve_read();
  }

  void write(std::shared_ptr<const std::vector<std::uint8_t>> message, MessageTransport::Done done) {
    const boost::system::error_code result = ended() ? write_error() : boost::system::error_code{};
    if (!result) upstream_.push_back(*message);
    asio::post(io_, [done = std::move(done), result] { done(result); });
  }

  void close_by_client() {
    closed_by_client_ = true;
    serve_read();
  }

  void send_down(std::vector<std::uint8_t> message) {
    if (ended()) return;
    downstream_.push_back(std::move(message));
    serve_read();
  }

  void drop_by_server() {
    dropped_by_server_ = true;
    serve_read();
  }

  std::vector<std::vector<std::uint8_t>> take_upstream() { return std::exchange(upstream_, {}); }
  bool connected() const { return connected_ && !ended(); }
  bool closed_by_client() const { return closed_by_client_; }

 private:
  bool ended() const { return closed_by_client_ || dropped_by_server_; }
  boost::system::error_code write_error() const {
    return closed_by_client_ ? asio::error::operation_aborted : asio::error::broken_pipe;
  }

  // Completes the outstanding read once there is something to say: the next
  // message, or how the connection ended. The message is taken when the
  // posted handler runs, so a close in between aborts the read as on a socket.
  void serve_read() {
    if (!pending_read_ || (downstream_.empty() && !ended())) return;
    asio::post(io_, [self = shared_from_this(), received = std::exchange(pending_read_, nullptr)] {
      self->complete_read(received);
    });
  }

  void complete_read(const MessageTransport::Received& received) {
    if (closed_by_client_) return received(asio::error::operation_aborted, {});
    if (downstream_.empty()) return received(asio::error::eof, {});
    const std::vector<std::uint8_t> message = std::move(downstream_.front());
    downstream_.pop_front();
    received({}, message);
  }

  asio::io_context& io_;
  boost::system::error_code refusal_;
  bool connected_ = false, closed_by_client_ = false, dropped_by_server_ = false;
  std::deque<std::vector<std::uint8_t>> downstream_;
  std::vector<std::vector<std::uint8_t>> upstream_;
  MessageTransport::Received pending_read_;
};

namespace {

// The session's end: everything goes through the shared connection.
class InMemoryTransport : public MessageTransport {
 public:
  explicit InMemoryTransport(std::shared_ptr<InMemoryConnection> connection) : connection_(std::move(connection)) {}

  void connect(int, Done done) override { connection_->connect(std::move(done)); }
  void read(Received received) override { connection_->read(std::move(received)); }
  void write(std::shared_ptr<const std::vector<std::uint8_t>> message, Done done) override {
    connection_->write(std::move(message), std::move(done));
  }
  void close() override { connection_->close_by_client(); }
  // Nothing is added to a message in memory.
  std::size_t framing_bytes(std::size_t, bool) const override { return 0; }

 private:
  std::shared_ptr<InMemoryConnection> connection_;
};

}  // namespace

InMemoryServerEnd::InMemoryServerEnd(asio::io_context& io) : io_(io) {}

TransportFactory InMemoryServerEnd::transports() {
  return [this]() -> std::shared_ptr<MessageTransport> {
    ++attempts_;
    newest_ = std::make_shared<InMemoryConnection>(io_, refusal_);
    return std::make_shared<InMemoryTransport>(newest_);
  };
}

void InMemoryServerEnd::send(std::vector<std::uint8_t> message) {
  if (newest_) newest_->send_down(std::move(message));
}

void InMemoryServerEnd::drop() {
  if (newest_) newest_->drop_by_server();
}

std::vector<std::vector<std::uint8_t>> InMemoryServerEnd::take_received() {
  return newest_ ? newest_->take_upstream() : std::vector<std::vector<std::uint8_t>>{};
}

bool InMemoryServerEnd::connected() const { return newest_ && newest_->connected(); }

bool InMemoryServerEnd::closed_by_client() const { return newest_ && newest_->closed_by_client(); }

}  // namespace fw::client
