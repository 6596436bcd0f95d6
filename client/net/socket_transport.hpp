#pragma once
// The network under a RoomSession: a MessageTransport over a real socket,
// WebSocket (Boost.Beast) or TCP with the protocol's length prefix
// (codec/messages.hpp, TcpDeframer). The one piece of the join command that
// opens connections to the room server; only the facewire-client
// executable links it (client/net), so the other parts' tests never need a
// socket.
#include <memory>

#include <boost/asio/io_context.hpp>

#include "message_transport.hpp"
#include "server_url.hpp"

namespace fw::client {

/// A transport for `url`'s scheme (not yet connected). Handlers keep the
/// transport alive until they ran.
std::shared_ptr<MessageTransport> make_socket_transport(boost::asio::io_context& io, const ServerUrl& url);

}  // namespace fw::client
