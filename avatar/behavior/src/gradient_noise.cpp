#include "fw/behavior/gradient_noise.hpp"

#include <cmath>

namespace fw::behavior {
namespace {

// A gradient in [-1,1] for lattice point `i`, from an integer hash.
float gradient(std::int64_t i, std::uint32_t seed) {
  std::uint32_t h = static_cast<std::uint32_t>(i) * 0x9E3779B1u ^ seed * 0x85EBCA77u;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  return static_cast<float>(h & 0xffffu) / 32767.5f - 1.0f;
}

// Perlin's improved fade 6t^5 - 15t^4 + 10t^3.
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

}  // namespace

float gradient_noise(float t, std::uint32_t seed) {
  const float floor_t = std::floor(t);
  const auto i = static_cast<std::int64_t>(floor_t);
  const float f = t - floor_t;
  const float a = gradient(i, seed) * f;
  const float b = gradient(i + 1, seed) * (f - 1.0f);
  return a + (b - a) * fade(f);
}

}  // namespace fw::behavior
