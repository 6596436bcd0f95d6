#pragma once
// Debian's Chromium, headless, for tests of what the browser shows. WebGL2
// runs on SwiftShader (no GPU here). The flags keep it off the network: this
// machine has none, and Chromium would otherwise keep trying.
#include <filesystem>
#include <string>

#include "run_command.hpp"

namespace fw::test {

inline constexpr const char* kChromium = "/usr/bin/chromium";

/// Runs headless Chromium on `url` with `action` (e.g. "--dump-dom" or
/// "--screenshot=FILE"), giving the page `virtual_ms` of virtual time to load
/// and animate. Returns what Chromium printed on stdout (stderr is dropped).
inline CommandResult headless_chromium(const std::string& url, const std::string& action, int virtual_ms = 5000) {
  const auto profile = std::filesystem::temp_directory_path() / ("facewire-chromium-" + std::to_string(::getpid()));
  const std::string command = std::string(kChromium) +
      " --headless --no-sandbox --no-first-run --disable-quic --disable-background-networking"
      " --disable-component-update --disable-sync --use-angle=swiftshader --enable-unsafe-swiftshader"
      " --user-data-dir=" + profile.string() + " --window-size=800,700 --virtual-time-budget=" +
      std::to_string(virtual_ms) + " " + action + " " + url + " 2>/dev/null";
  CommandResult result = run_command(command);
  std::filesystem::remove_all(profile);
  return result;
}

}  // namespace fw::test
