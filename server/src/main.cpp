// facewire-server: the room server, photo preparation and tools. With no
// subcommand it serves (`make run`).
#include <iostream>

#include <CLI/CLI.hpp>

#include "fw/photo/photo_limits.hpp"
#include "prep_command.hpp"
#include "script_command.hpp"
#include "serve_command.hpp"

int main(int argc, char** argv) {
  fw::photo::enforce_decoder_pixel_limit(argv);
  CLI::App app{"facewire server: hosts the avatars' faces and streams them to clients"};
  fw::server::add_serve_command(app);
  fw::server::add_prep_command(app);
  fw::server::add_script_command(app);

  struct Unbuilt {
    const char* name;
    const char* what;
    const char* arrives_with;
  };
  const Unbuilt unbuilt[] = {
      {"token", "Mint a join token", "the room server"}};
  for (const auto& [name, what, arrives_with] : unbuilt) {
    CLI::App* cmd = app.add_subcommand(name, std::string(what) + " (not yet built)");
    cmd->allow_extras();
    cmd->callback([name = std::string(name), arrives = std::string(arrives_with)] {
      std::cerr << "facewire-server " << name << ": not yet built; it arrives with " << arrives << ".\n";
      std::exit(3);
    });
  }

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
