#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `token --room R [--name N] [--ttl S] [--url U] [--auth-secret X]`:
/// prints a join token for a server started with the same secret, and on a
/// second line the invite link (invite_link.hpp) that carries it.
void add_token_command(CLI::App& app);

}  // namespace fw::server
