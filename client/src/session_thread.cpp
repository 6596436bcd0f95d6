#include "session_thread.hpp"

#include <chrono>

#include <boost/asio/post.hpp>

namespace fw::client {

SessionThread::SessionThread(SessionOptions options, RoomState& state, OpenTransport open_transport)
    : open_transport_(std::move(open_transport)),
      session_(io_, std::move(options), state, [this] { return open_transport_(io_); }) {
  session_.start();
  thread_ = std::thread([this] { io_.run(); });
}

SessionThread::~SessionThread() { stop(); }

void SessionThread::stop() {
  if (!thread_.joinable()) return;
  boost::asio::post(io_, [this] { session_.stop(); });
  // The session's sockets are closed; give their handlers a moment, then stop.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  io_.stop();
  thread_.join();
}

}  // namespace fw::client
