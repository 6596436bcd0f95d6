// facewire-client: the thin client. Renders faces from compact parameters;
// links only codec, avatar/model and avatar/render (and Asio for the network).
// The commands run the steps of the parts below; this file gives them the
// sockets (client/net).
#include <iostream>

#include <CLI/CLI.hpp>

#include "avatar_upload.hpp"
#include "delete_avatar_command.hpp"
#include "join_command.hpp"
#include "render_command.hpp"
#include "socket_transport.hpp"

int main(int argc, char** argv) {
  CLI::App app{"facewire thin client: render avatars, join rooms"};
  app.require_subcommand(1);
  fw::client::add_render_command(app);
  fw::client::add_delete_avatar_command(app);
  fw::client::add_join_command(
      app, {fw::client::make_socket_transport, fw::client::upload_avatar, fw::client::async_upload_avatar});

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints what was wrong; every refused command line exits with 2,
    // as the commands' own checks do (help exits with 0).
    return app.exit(e) == 0 ? 0 : 2;
  }
  return 0;
}
