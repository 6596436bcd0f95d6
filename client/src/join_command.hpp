#pragma once
// `facewire-client join`: join a room as an avatar, receive and show the
// room's faces, print link statistics.
#include <CLI/CLI.hpp>

namespace fw::client {

/// Adds the `join` subcommand to `app`; its callback runs the session and
/// exits with 0 when it ends as asked (frames, seconds, Ctrl-C), 2 on bad
/// input or when the server refuses the client, 1 when it never got in or
/// an output failed.
void add_join_command(CLI::App& app);

}  // namespace fw::client
