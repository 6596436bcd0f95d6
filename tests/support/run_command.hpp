#pragma once
// Runs a facewire executable as a person would and captures what it says.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace fw::test {

struct CommandResult {
  int status = -1;     ///< exit status, or -1 if it did not exit normally
  std::string output;  ///< stdout, and stderr unless left out
};

/// Runs `command_line` through the shell, capturing stdout and, if
/// `with_stderr`, stderr interleaved with it (otherwise stderr goes to the
/// test's own, where ctest shows it on failure).
inline CommandResult run_command(const std::string& command_line, bool with_stderr = true) {
  CommandResult result;
  FILE* pipe = ::popen((command_line + (with_stderr ? " 2>&1" : "")).c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int raw = ::pclose(pipe);
  if (WIFEXITED(raw)) result.status = WEXITSTATUS(raw);
  return result;
}

/// Path of an executable of this build (build/bin/NAME).
inline std::string bin(const std::string& name) { return std::string(FW_BIN_DIR) + "/" + name; }

}  // namespace fw::test
