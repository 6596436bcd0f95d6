#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `simulate --avatars N --seconds S --seed K -o scene.fws` to `app`:
/// runs a room (behavior and the physics face) without any network, the
/// avatars joining one after another as in the paper's experiment, and
/// writes every avatar's FaceParams per tick, unquantised, with the room's
/// events (fw/behavior/scene_file.hpp). Prints a JSON summary.
void add_simulate_command(CLI::App& app);

}  // namespace fw::server
