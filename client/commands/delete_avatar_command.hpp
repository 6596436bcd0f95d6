#pragma once
// facewire-client delete-avatar: deletes one's avatar and the photo it was
// made from on a server (DELETE /api/avatars/ID with its key in
// X-Avatar-Key, server/PROTOCOL.md section 8), with the asset id and key
// that `join --photo` printed when it uploaded them. Socket glue, so it
// lives in the executable.
#include <CLI/CLI.hpp>

namespace fw::client {

void add_delete_avatar_command(CLI::App& app);

}  // namespace fw::client
