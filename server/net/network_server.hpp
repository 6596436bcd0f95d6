#pragma once
// `facewire-server serve`: a ServerCore behind a listener for HTTP and
// WebSocket and, when configured, one for length-prefixed TCP, run on the
// I/O threads until SIGINT or SIGTERM has drained it.
#include "server_config.hpp"

namespace fw::server {

/// Runs the server; the process's exit status: 0 after a drain, 2 (and a
/// message on stderr saying what to change) when it cannot start.
int run_network_server(const ServerConfig& config);

}  // namespace fw::server
