#include "command_line.hpp"

#include <iostream>
#include <string>
#include <vector>

namespace fw::server {
namespace {

bool asks_for_help(const std::string& argument) { return argument == "-h" || argument == "--help"; }

/// The arguments after the program's name, with `serve` in front when they
/// name no subcommand: serve is the default.
std::vector<std::string> with_default_subcommand(int argc, const char* const* argv) {
  std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.empty() || (arguments.front().starts_with("-") && !asks_for_help(arguments.front())))
    arguments.insert(arguments.begin(), "serve");
  return arguments;
}

/// "facewire-server serve", say: the command a usage error belongs to.
std::string command_name(const CLI::App& app) {
  std::string name = "facewire-server";
  for (const CLI::App* sub : app.get_subcommands()) name += " " + sub->get_name();
  return name;
}

int usage_error(const CLI::App& app, const CLI::ParseError& error) {
  const std::string command = command_name(app);
  std::cerr << command << ": " << error.what() << "\nRun '" << command << " --help' for its options.\n";
  return kUsageError;
}

}  // namespace

int run_command_line(CLI::App& app, int argc, const char* const* argv) {
  std::vector<std::string> arguments = with_default_subcommand(argc, argv);
  std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
  try {
    app.parse(arguments);
  } catch (const CLI::ParseError& error) {
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);  // --help
    return usage_error(app, error);
  }
  if (app.get_subcommands().empty()) {
    std::cerr << app.help();
    return kUsageError;
  }
  return 0;
}

}  // namespace fw::server
