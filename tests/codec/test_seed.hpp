#pragma once
// Seeds for randomised tests: FW_TEST_SEED=n repeats a run; every test that
// uses one prints it, so a failure can be replayed.
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

namespace fw::codec::test {

/// The seed of this run (FW_TEST_SEED, or the clock), printed with `what`.
inline std::uint64_t seed(const std::string& what) {
  std::uint64_t s = 0;
  if (const char* env = std::getenv("FW_TEST_SEED")) {
    s = std::strtoull(env, nullptr, 10);
  } else {
    s = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  }
  std::cout << "[ seed     ] " << what << ": FW_TEST_SEED=" << s << "\n";
  return s;
}

}  // namespace fw::codec::test
