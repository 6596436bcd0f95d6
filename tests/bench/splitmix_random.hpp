#pragma once
// splitmix64: the same numbers on every platform (the standard library's
// distributions are not specified bit for bit, and the codec's golden
// vectors depend on the synthetic scenes these numbers make).
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace fw::bench {

class SplitMixRandom {
 public:
  explicit SplitMixRandom(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double exponential(double mean) { return -mean * std::log(1.0 - uniform(0.0, 1.0)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  /// An index in [0, n).
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(next() % n); }
  int pick(int n) { return static_cast<int>(index(static_cast<std::size_t>(n))); }

 private:
  std::uint64_t state_;
};

}  // namespace fw::bench
