#pragma once
// The command line of facewire-server: its subcommands, `serve` when none
// is named, and one exit status for every usage error.
#include <CLI/CLI.hpp>

namespace fw::server {

/// Exit status of a command line a person got wrong (an unknown flag, a bad
/// or missing value), as of any other bad input.
inline constexpr int kUsageError = 2;

/// Parses the arguments with `app`, whose subcommands run from their
/// callbacks, and returns the exit status. A command line that starts with
/// a flag (or is empty) is serve's: `facewire-server --http ADDR:PORT`
/// serves. A usage error prints what was wrong, naming the flag, and
/// returns kUsageError; --help prints the help and returns 0.
int run_command_line(CLI::App& app, int argc, const char* const* argv);

}  // namespace fw::server
