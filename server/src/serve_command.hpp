#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `serve` (the default when no subcommand is given) to `app`.
/// Returns the subcommand so main can run it by default.
CLI::App* add_serve_command(CLI::App& app);

}  // namespace fw::server
