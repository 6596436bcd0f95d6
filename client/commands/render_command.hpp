#pragma once
// `facewire-client render`: one face to a PNG.
#include <CLI/CLI.hpp>

namespace fw::client {

/// Adds the `render` subcommand to `app`; its callback runs the command and
/// exits with 0 on success, 2 on bad input.
void add_render_command(CLI::App& app);

}  // namespace fw::client
