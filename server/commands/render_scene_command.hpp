#pragma once
#include <CLI/CLI.hpp>

namespace fw::server {

/// Adds `render-scene SCENE (--out DIR | --y4m FILE|-)` to `app`: draws a
/// recorded scene (facewire-server simulate) through the renderer, every
/// avatar a generic face with its own look, seated where the room seated
/// it, as PNG frames or a Y4M video.
void add_render_scene_command(CLI::App& app);

}  // namespace fw::server
