// facewire-server: the room server, photo preparation and tools. With no
// subcommand it serves (`make run`).
#include <iostream>

#include <CLI/CLI.hpp>

#include "fw/photo/photo_limits.hpp"
#include "prep_command.hpp"
#include "render_scene_command.hpp"
#include "script_command.hpp"
#include "serve_command.hpp"
#include "simulate_command.hpp"
#include "token_command.hpp"

int main(int argc, char** argv) {
  fw::photo::enforce_decoder_pixel_limit(argv);
  CLI::App app{"facewire server: hosts the avatars' faces and streams them to clients"};
  fw::server::add_serve_command(app);
  fw::server::add_prep_command(app);
  fw::server::add_script_command(app);
  fw::server::add_simulate_command(app);
  fw::server::add_render_scene_command(app);
  fw::server::add_token_command(app);

  try {
    if (argc == 1) app.parse("serve", false);  // no subcommand: serve with the embedded defaults
    else app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (app.get_subcommands().empty()) {
    std::cerr << app.help();
    return 2;
  }
  return 0;
}
