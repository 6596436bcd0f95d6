#pragma once
// The RoomSession on a network thread of its own, beside `join`'s render
// loop: it starts at construction and runs until stop() (or destruction),
// which closes the connection and joins the thread. The two threads share
// only the RoomState, under its mutex.
#include <functional>
#include <memory>
#include <thread>

#include <boost/asio/io_context.hpp>

#include "message_transport.hpp"
#include "room_session.hpp"
#include "room_state.hpp"

namespace fw::client {

/// How the session reaches its servers, given the thread's io_context.
struct SessionNetwork {
  /// A transport to the server of this index (of SessionOptions::servers).
  std::function<std::shared_ptr<MessageTransport>(boost::asio::io_context& io, std::size_t server)> open_transport;
  /// Uploads the person's face to the server of this index, calling `done`
  /// on `io`; empty when the person brings none.
  std::function<void(boost::asio::io_context& io, std::size_t server, ReuploadDone done)> upload_avatar;
};

class SessionThread {
 public:
  /// Opens a transport on the thread's io_context (each connection attempt).
  using OpenTransport = std::function<std::shared_ptr<MessageTransport>(boost::asio::io_context& io)>;

  /// One server.
  SessionThread(SessionOptions options, RoomState& state, OpenTransport open_transport);
  /// The servers of options.servers.
  SessionThread(SessionOptions options, RoomState& state, SessionNetwork network);
  ~SessionThread();
  SessionThread(const SessionThread&) = delete;
  SessionThread& operator=(const SessionThread&) = delete;

  /// Hands a chat line the person typed to the session (RoomSession::say);
  /// from any thread.
  void say(std::string line);

  /// Closes the session's connection, gives its handlers a moment, then
  /// stops the io_context and joins the thread. Calls after the first do nothing.
  void stop();

 private:
  static SessionOptions with_uploads(SessionOptions options, const SessionNetwork& network,
                                     boost::asio::io_context& io);

  boost::asio::io_context io_;
  SessionNetwork network_;
  RoomSession session_;
  std::thread thread_;
};

}  // namespace fw::client
