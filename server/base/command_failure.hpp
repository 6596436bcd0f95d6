#pragma once
// How the offline subcommands (simulate, render-scene) stop on input they
// cannot use: the message on stderr after the command's name, and exit code
// 2, the code of a usage error (README).
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

namespace fw::server {

[[noreturn]] inline void fail_command(std::string_view command, const std::string& message) {
  std::cerr << "facewire-server " << command << ": " << message << "\n";
  std::exit(2);
}

}  // namespace fw::server
