#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `script [--grammar FILE] FILE` to `app`: parses a file of face-script
/// sentences (fw/script) and prints their meaning as JSON on stdout, or the
/// errors, one `FILE:LINE:COLUMN: message` a line on stderr, with exit
/// status 2. Warnings go to stderr in the same form and do not change the
/// status.
void add_script_command(CLI::App& app);

}  // namespace fw::server
