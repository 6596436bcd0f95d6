// facewire-server: the room server, photo preparation and tools. Without a
// subcommand, or with flags only, it serves (`make run`).
#include <CLI/CLI.hpp>

#include "command_line.hpp"
#include "prep_command.hpp"
#include "render_scene_command.hpp"
#include "script_command.hpp"
#include "serve_command.hpp"
#include "simulate_command.hpp"
#include "token_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"facewire server: hosts the avatars' faces and streams them to clients"};
  fw::server::add_serve_command(app);
  fw::server::add_prep_command(app);
  fw::server::add_script_command(app);
  fw::server::add_simulate_command(app);
  fw::server::add_render_scene_command(app);
  fw::server::add_token_command(app);
  return fw::server::run_command_line(app, argc, argv);
}
