#pragma once
// Individual variation of the facial muscles: no two people's muscles are
// alike. Dissections find the same muscles laid and sized differently from
// face to face (Pessa, Zadoo, Adrian, Yuan, Aydelotte & Garza 1998,
// "Variability of the midfacial muscles: analysis of 50 hemifacial cadaver
// dissections", Plast. Reconstr. Surg. 102(6): a bifid zygomaticus major in
// about a third of hemifaces, and the levators' and zygomatic minor's size
// and course varying), and the muscles that the universal expressions
// need (orbicularis oris and oculi, zygomaticus major, depressor anguli
// oris, frontalis) are found in everyone while others (risorius,
// zygomaticus minor, procerus among them) vary down to being absent
// (Waller, Cray & Burrows 2008, "Selection for universal facial emotion",
// Emotion 8(3)).
//
// A muscle's force goes with its cross-section, so a face's muscles are
// stronger or weaker than the reference table by a factor drawn per muscle
// pair, both sides alike but for a smaller asymmetry (faces are nearly,
// never exactly, symmetric), from a seed: the avatar's asset id, so that an
// avatar moves alike in every room and on every server. The spread is a
// modelling choice kept inside what keeps each action unit recognisable
// (the AU basis stays the reference face's): kPairVariation between
// people, kSideVariation between the two sides, the muscles that the
// universal expressions do not need (Waller et al.) twice as much.
#include <array>
#include <cstdint>
#include <string_view>

#include "fw/physics/facial_muscles.hpp"

namespace fw::physics {

/// SimulationOptions::individual_variation of a person's face: what rooms
/// give every face, and the behaviour corpus is recorded with.
inline constexpr float kPersonVariation = 1.0f;
/// Largest share a muscle pair is stronger or weaker than the table.
inline constexpr float kPairVariation = 0.2f;
/// Largest share one side differs from the pair besides.
inline constexpr float kSideVariation = 0.05f;
/// How much more the muscles not needed for the universal expressions vary.
inline constexpr float kVariableMuscleFactor = 2.0f;

/// Per muscle (facial_muscles.hpp order) the factor on its table strength:
/// 1 + scale (kPairVariation u_pair + kSideVariation u_side), u uniform in
/// [-1, 1) from `seed` (SplitMix64: the same on every platform); scale 0
/// gives all ones, 1 a typical person, and the variable muscles go twice
/// as far. Every factor lies in
/// [1 - scale k (kPairVariation + kSideVariation), 1 + ...] with k 1 or
/// kVariableMuscleFactor.
std::array<float, kMuscleCount> muscle_strength_factors(std::uint64_t seed, float scale = 1.0f);

/// A seed from an avatar's asset id (any text; FNV-1a 64).
std::uint64_t variation_seed(std::string_view asset);

/// Whether the universal expressions need muscle pair `pair` (0 .. 20,
/// facial_muscle_definitions() order) in everyone (Waller et al. 2008).
bool universally_present(std::size_t pair);

}  // namespace fw::physics
