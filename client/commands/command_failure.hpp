#pragma once
// How the client's commands (join, render) stop: the message on stderr after
// the command's name, and the exit status the README gives for the cause.
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

namespace fw::client {

[[noreturn]] inline void fail_command(std::string_view command, int status, const std::string& message) {
  std::cerr << "facewire-client " << command << ": " << message << "\n";
  std::exit(status);
}

}  // namespace fw::client
