#pragma once
// The benchmarks' JSON gives figures to a sensible unit, not every digit a
// double holds.
#include <cmath>

namespace fw::bench {

/// `v` to the nearest multiple of `unit` (thousandths unless told).
inline double rounded(double v, double unit = 0.001) { return std::round(v / unit) * unit; }

}  // namespace fw::bench
