// facewire-client: the thin client. Renders faces from compact parameters;
// links only codec, avatar/model and avatar/render (and Asio for the network).
#include <iostream>

#include <CLI/CLI.hpp>

#include "render_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"facewire thin client: render avatars, join rooms"};
  app.require_subcommand(1);
  fw::client::add_render_command(app);

  CLI::App* join = app.add_subcommand("join", "Join a room (not yet built)");
  join->allow_extras();
  join->callback([] {
    std::cerr << "facewire-client join: not yet built; joining rooms arrives with the room server.\n";
    std::exit(3);
  });

  CLI11_PARSE(app, argc, argv);
  return 0;
}
