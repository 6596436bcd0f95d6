#include "in_memory_session.hpp"

#include <boost/asio/post.hpp>

namespace fw::server {

namespace net = boost::asio;

InMemorySession::InMemorySession(const SessionServices& services, net::any_io_executor executor, std::string peer)
    : ClientSession(services, std::move(executor), std::move(peer)) {}

std::shared_ptr<InMemorySession> InMemorySession::self() {
  return std::static_pointer_cast<InMemorySession>(shared_from_this());
}

std::size_t InMemorySession::framing_bytes(std::size_t message_bytes) const {
  return message_bytes < 128 ? 1 : message_bytes < 16384 ? 2 : 3;
}

void InMemorySession::run() {
  net::post(executor_, [self = self()] { self->start(); });
}

// Upstream messages arrive whole through push(): there is no read to start.
void InMemorySession::start_reading() {}

void InMemorySession::push(std::vector<std::uint8_t> message) {
  net::post(executor_, [self = self(), message = std::move(message)] {
    self->note_received(message.size());
    self->on_message(message);
  });
}

void InMemorySession::hang_up() {
  net::post(executor_, [self = self()] {
    self->fail_pending_write();
    self->on_transport_closed();
    std::lock_guard lock(self->mutex_);
    self->gone_ = true;
  });
}

void InMemorySession::set_reading(bool reading) {
  net::post(executor_, [self = self(), reading] {
    self->reading_ = reading;
    if (reading && self->pending_) self->complete_write();
  });
}

void InMemorySession::start_write(const SharedBytes& message) {
  pending_ = message;
  // Completed later, never inside start_write, as a socket's write would be.
  if (reading_) net::post(executor_, [self = self()] {
      if (self->reading_ && self->pending_) self->complete_write();
    });
}

void InMemorySession::complete_write() {
  const SharedBytes message = std::move(pending_);
  pending_.reset();
  {
    std::lock_guard lock(mutex_);
    written_.push_back(message);
  }
  on_write_done(true, message->size() + framing_bytes(message->size()));
}

void InMemorySession::fail_pending_write() {
  // As a closed socket cancels its write in progress.
  if (!pending_) return;
  pending_.reset();
  on_write_done(false, 0);
}

void InMemorySession::shutdown_transport(codec::CloseCode code, const std::string&, bool abort) {
  {
    std::lock_guard lock(mutex_);
    shut_down_ = code;
    aborted_ = abort;
  }
  // The closing message, if any, has been written: the peer has it, and the
  // pipe closes at once (a socket would wait for the peer to close too).
  fail_pending_write();
  on_transport_closed();
  std::lock_guard lock(mutex_);
  gone_ = true;
}

std::vector<SharedBytes> InMemorySession::take_written() {
  std::lock_guard lock(mutex_);
  std::vector<SharedBytes> out(std::make_move_iterator(written_.begin()), std::make_move_iterator(written_.end()));
  written_.clear();
  return out;
}

std::optional<codec::CloseCode> InMemorySession::shut_down() const {
  std::lock_guard lock(mutex_);
  return shut_down_;
}

bool InMemorySession::aborted() const {
  std::lock_guard lock(mutex_);
  return aborted_;
}

bool InMemorySession::gone() const {
  std::lock_guard lock(mutex_);
  return gone_;
}

}  // namespace fw::server
