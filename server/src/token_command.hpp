#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `token --room R [--name N] [--ttl S] [--auth-secret X]`: prints a
/// join token for a server started with the same secret.
void add_token_command(CLI::App& app);

}  // namespace fw::server
