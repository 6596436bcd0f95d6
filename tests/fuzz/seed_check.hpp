#pragma once
// Seeds that have gone stale: a seed the reader refuses at its first check
// (an old version, say) explores nothing past that check, and the fuzzer
// says nothing about it. A target that is given FW_FUZZ_SEEDS_MUST_READ
// (run_fuzzer.sh sets it while it runs the repository's seeds once, before
// fuzzing, for the targets whose fw_fuzz_target says SEEDS_MUST_READ) calls
// seed_refused() where it refuses an input: with the variable set, that
// names the reason and aborts, so the ctest fails and says to make the
// seeds again.
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace fw::fuzz {

inline bool seeds_must_read() {
  static const bool set = std::getenv("FW_FUZZ_SEEDS_MUST_READ") != nullptr;
  return set;
}

/// Call where the input is refused; `why` is the reader's reason.
inline void seed_refused(std::string_view why) {
  if (!seeds_must_read()) return;
  std::fprintf(stderr,
               "a seed in the repository is refused: %.*s\n"
               "make the seeds again with this version (tests/fuzz/CMakeLists.txt says how for each target)\n",
               static_cast<int>(why.size()), why.data());
  std::abort();
}

}  // namespace fw::fuzz
