#pragma once
// One-dimensional gradient (Perlin) noise: the small, never-repeating motion a
// living head and eyes show at rest.
#include <cstdint>

namespace fw::behavior {

/// Perlin gradient noise of `t` (any real), in about [-0.5, 0.5], smooth
/// (C2 through the quintic fade), zero at integers. `seed` picks an
/// independent sequence, so every avatar moves differently but reproducibly.
float gradient_noise(float t, std::uint32_t seed);

}  // namespace fw::behavior
