#pragma once
// `facewire-client join`: join a room as an avatar, receive and show the
// room's faces, print link statistics.
#include <functional>
#include <memory>

#include <CLI/CLI.hpp>
#include <boost/asio/io_context.hpp>

#include "message_transport.hpp"
#include "own_avatar.hpp"
#include "server_url.hpp"

namespace fw::client {

/// How `join` reaches the server. No part below commands opens a socket:
/// facewire-client's main.cpp passes its socket transport and HTTP upload.
struct JoinNetwork {
  /// A transport to `url` on `io` for each connection attempt.
  std::function<std::shared_ptr<MessageTransport>(boost::asio::io_context& io, const ServerUrl& url)> open_transport;
  AvatarUploader upload_avatar;  ///< before the session, to the first server that answers
  /// During the session, to another server of the list that does not know the face.
  AsyncAvatarUploader upload_avatar_async;
};

/// Adds the `join` subcommand to `app`; its callback runs the session and
/// exits with 0 when it ends as asked (frames, seconds, Ctrl-C), 2 on bad
/// input or when the server refuses the client, 1 when it never got in or
/// an output failed.
void add_join_command(CLI::App& app, JoinNetwork network);

}  // namespace fw::client
