#include "token_command.hpp"

#include <chrono>
#include <iostream>

#include "display_name.hpp"
#include "invite_link.hpp"
#include "join_token.hpp"
#include "room_registry.hpp"

namespace fw::server {
namespace {

struct TokenArgs {
  std::string room;
  std::string name;
  std::int64_t ttl_seconds = 86400;
  std::string secret;
  std::string url = "http://127.0.0.1:8080/";
};

int mint(const TokenArgs& args) {
  if (args.secret.empty()) {
    std::cerr << "facewire-server token: no secret; pass --auth-secret or set FACEWIRE_AUTH_SECRET to the server's\n";
    return 2;
  }
  if (!is_valid_room_name(args.room)) {
    std::cerr << "facewire-server token: --room: room names are 1 to 64 characters of A-Z a-z 0-9 _ - .\n";
    return 2;
  }
  // The name as the server will compare it: normalised, and refused when it
  // could not be a display name.
  std::string name;
  if (const std::string why = normalize_display_name(args.name, name); !why.empty()) {
    std::cerr << "facewire-server token: --name: " << why << "\n";
    return 2;
  }
  const auto now = std::chrono::duration_cast<std::chrono::seconds>(
                       std::chrono::system_clock::now().time_since_epoch())
                       .count();
  const std::string token = mint_join_token({args.room, name, now + args.ttl_seconds}, args.secret);
  std::string error;
  const auto link = invite_link(args.url, args.room, name, token, error);
  if (!link) {
    std::cerr << "facewire-server token: --url: " << error << "\n";
    return 2;
  }
  // The token alone on the first line (for scripts and the native client's
  // --token), the link for a browser on the second.
  std::cout << token << "\n" << *link << "\n";
  return 0;
}

}  // namespace

void add_token_command(CLI::App& app) {
  auto args = std::make_shared<TokenArgs>();
  CLI::App* cmd = app.add_subcommand("token", "Mint a join token for one person (a name) in one room");
  cmd->add_option("--room", args->room, "the room the token opens")->required();
  // A token admits one person at a time, under one name: one without a
  // name would admit whoever saw it.
  cmd->add_option("--name", args->name, "the display name of the person it invites")->required();
  cmd->add_option("--ttl", args->ttl_seconds, "seconds until it expires")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{366} * 86400))
      ->capture_default_str();
  cmd->add_option("--url", args->url, "the server's public address, the start of the invite link")
      ->envname("FACEWIRE_PUBLIC_URL")
      ->capture_default_str();
  cmd->add_option("--auth-secret", args->secret, "the server's --auth-secret")->envname("FACEWIRE_AUTH_SECRET");
  cmd->callback([args] { std::exit(mint(*args)); });
}

}  // namespace fw::server
