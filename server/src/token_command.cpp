#include "token_command.hpp"

#include <chrono>
#include <iostream>

#include "join_token.hpp"

namespace fw::server {
namespace {

struct TokenArgs {
  std::string room;
  std::string name;
  std::int64_t ttl_seconds = 86400;
  std::string secret;
};

int mint(const TokenArgs& args) {
  if (args.secret.empty()) {
    std::cerr << "facewire-server token: no secret; pass --auth-secret or set FACEWIRE_AUTH_SECRET to the server's\n";
    return 2;
  }
  const auto now = std::chrono::duration_cast<std::chrono::seconds>(
                       std::chrono::system_clock::now().time_since_epoch())
                       .count();
  std::cout << mint_join_token({args.room, args.name, now + args.ttl_seconds}, args.secret) << "\n";
  return 0;
}

}  // namespace

void add_token_command(CLI::App& app) {
  auto args = std::make_shared<TokenArgs>();
  CLI::App* cmd = app.add_subcommand("token", "Mint a join token for one room (and optionally one name)");
  cmd->add_option("--room", args->room, "the room the token opens")->required();
  cmd->add_option("--name", args->name, "the only display name it admits (default: any)");
  cmd->add_option("--ttl", args->ttl_seconds, "seconds until it expires")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{366} * 86400))
      ->capture_default_str();
  cmd->add_option("--auth-secret", args->secret, "the server's --auth-secret")->envname("FACEWIRE_AUTH_SECRET");
  cmd->callback([args] { std::exit(mint(*args)); });
}

}  // namespace fw::server
