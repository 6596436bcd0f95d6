#pragma once
// How a benchmark stops when it cannot run (a missing file, a bad option):
// the message on stderr after the benchmark's name, and exit code 2.
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

namespace fw::bench {

[[noreturn]] inline void fail_bench(std::string_view benchmark, const std::string& message) {
  std::cerr << "facewire-bench " << benchmark << ": " << message << "\n";
  std::exit(2);
}

}  // namespace fw::bench
