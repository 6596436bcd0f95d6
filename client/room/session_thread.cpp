#include "session_thread.hpp"

#include <chrono>
#include <future>

#include <boost/asio/post.hpp>

namespace fw::client {

SessionThread::SessionThread(SessionOptions options, RoomState& state, OpenTransport open_transport)
    : SessionThread(std::move(options), state,
                    SessionNetwork{[open = std::move(open_transport)](boost::asio::io_context& io, std::size_t) {
                                     return open(io);
                                   },
                                   {}}) {}

SessionThread::SessionThread(SessionOptions options, RoomState& state, SessionNetwork network)
    : network_(std::move(network)),
      session_(io_, with_uploads(std::move(options), network_, io_), state,
               [this](std::size_t server) { return network_.open_transport(io_, server); }) {
  session_.start();
  thread_ = std::thread([this] { io_.run(); });
}

// The session's uploads run on the thread's io_context, beside its connection.
SessionOptions SessionThread::with_uploads(SessionOptions options, const SessionNetwork& network,
                                           boost::asio::io_context& io) {
  if (network.upload_avatar)
    options.reupload = [&network, &io](std::size_t server, ReuploadDone done) {
      network.upload_avatar(io, server, std::move(done));
    };
  return options;
}

SessionThread::~SessionThread() { stop(); }

void SessionThread::say(std::string line) {
  boost::asio::post(io_, [this, line = std::move(line)] { session_.say(line); });
}

void SessionThread::stop() {
  if (!thread_.joinable()) return;
  // The session closes on its own thread; wait until it has (a busy machine
  // may take longer than any fixed pause to get there), then give the
  // sockets' handlers a moment, then stop.
  // A context already out of work (its run() returned) runs nothing
  // posted, so it is not waited for, and the wait is bounded anyway.
  if (!io_.stopped()) {
    std::promise<void> stopped;
    boost::asio::post(io_, [this, &stopped] {
      session_.stop();
      stopped.set_value();
    });
    stopped.get_future().wait_for(std::chrono::seconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  io_.stop();
  thread_.join();
}

}  // namespace fw::client
