#include "fw/physics/muscle_variation.hpp"

#include <array>
#include <string_view>

namespace fw::physics {
namespace {

// SplitMix64: a fixed, portable generator, so a seed means the same face
// on every platform.
std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Uniform in [-1, 1).
float centred_uniform(std::uint64_t& state) {
  return static_cast<float>(double(splitmix64(state) >> 11) / double(1ULL << 53) * 2.0 - 1.0);
}

// The pairs dissection finds absent or much reduced in some people
// (Waller et al. 2008; Pessa et al. 1998 for the zygomatic minor).
constexpr std::array<std::string_view, 3> kVariable = {"procerus", "zygomatic_minor", "risorius"};

}  // namespace

bool universally_present(std::size_t pair) {
  const auto& definitions = facial_muscle_definitions();
  if (pair >= definitions.size()) return false;
  for (std::string_view name : kVariable)
    if (definitions[pair].name == name) return false;
  return true;
}

std::array<float, kMuscleCount> muscle_strength_factors(std::uint64_t seed, float scale) {
  std::array<float, kMuscleCount> factor{};
  std::uint64_t state = seed;
  for (std::size_t pair = 0; pair < kMusclesPerSide; ++pair) {
    const float spread = scale * (universally_present(pair) ? 1.0f : kVariableMuscleFactor);
    const float shared = kPairVariation * centred_uniform(state);
    // Left is 2 pair, right 2 pair + 1 (facial_muscles.hpp).
    for (std::size_t side = 0; side < 2; ++side)
      factor[2 * pair + side] = 1.0f + spread * (shared + kSideVariation * centred_uniform(state));
  }
  return factor;
}

std::uint64_t variation_seed(std::string_view asset) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : asset) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return hash;
}

}  // namespace fw::physics
