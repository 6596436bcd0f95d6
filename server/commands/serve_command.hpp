#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `serve` to `app`: its flags, the environment variables and config
/// file behind them, and a callback that runs the server and exits with its
/// status. It is the default subcommand (command_line.hpp).
CLI::App* add_serve_command(CLI::App& app);

}  // namespace fw::server
