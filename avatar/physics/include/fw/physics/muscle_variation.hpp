#pragma once
// Individual variation of the facial muscles: no two people's muscles are
// alike. Dissections find the same muscles sized and laid differently from
// face to face (Pessa, Zadoo, Adrian, Yuan, Aydelotte & Garza 1998,
// "Variability of the midfacial muscles: analysis of 50 hemifacial cadaver
// dissections", Plast. Reconstr. Surg. 102(6): the levators' and the
// zygomatic minor's size and course varying), and the muscles that the
// universal expressions need (orbicularis oris and oculi, zygomaticus
// major, depressor anguli oris, frontalis) are found in everyone while
// others (risorius, zygomaticus minor, procerus among them) vary down to
// being absent (Waller, Cray & Burrows 2008, "Selection for universal
// facial emotion", Emotion 8(3)).
//
// Two things vary per person, both drawn from a seed (the avatar's asset
// id, so that an avatar moves alike in every room and on every server),
// per muscle pair, both sides alike but for a smaller asymmetry (faces are
// nearly, never exactly, symmetric):
//
// - Strength. A muscle's force goes with its cross-section, so a face's
//   muscles are stronger or weaker than the reference table by a factor:
//   kPairVariation between people, kSideVariation between the two sides,
//   the muscles the universal expressions do not need (Waller et al.)
//   twice as much. The spread is a modelling choice kept inside what keeps
//   each action unit recognisable.
// - Course. Each linear muscle's origin and insertion are moved in the face
//   plane within the millimetres dissections report for that muscle
//   (course_spread, muscle_variation.cpp, where each figure is cited); the
//   muscles converging on the modiolus move their insertion together, as
//   the modiolus lies lateral to, above or below the mouth's corner from
//   person to person (Shimada & Gasser 1989); a third of hemifaces have a
//   bifid zygomaticus major, its inferior bundle inserting below the
//   corner (Pessa, Zadoo, Garza, Adrian, Dewitt & Garza 1998, Clin. Anat.
//   11: 17 of 50). The sphincters ring their apertures and the jaw muscles
//   move no skin: their courses stay the table's. Each face lays its moved
//   muscles on the shared tissue model (muscle_course.hpp); the model, and
//   the projective solver's factored matrix, stay the reference's.
//
// The AU basis stays the reference face's (scale 0): each person's action
// units are measured against it, so every action unit must stay
// recognisable under any draw. Where a study gives categories rather than
// millimetres (the modiolus, the risorius' origin), the spread is the part
// of its range that keeps them so (face_simulation_test.cpp).
#include <array>
#include <cstdint>
#include <string_view>

#include <glm/vec2.hpp>

#include "fw/physics/facial_muscles.hpp"

namespace fw::physics {

/// SimulationOptions::individual_variation of a person's face: what rooms
/// give every face, and the behaviour corpus is recorded with.
inline constexpr float kPersonVariation = 1.0f;
/// SimulationOptions::course_variation of a person's face, in rooms and in
/// the behaviour corpus alike. 0 for now: with every person's courses at
/// the literature's spread (1) the six corrective components fitted on the
/// corpus cut the held-out error only to 0.53 of it (0.52 at half the
/// spread), above the bound of 0.5; the per-person shapes are what
/// one basis shared by every face cannot rebuild (avatar/physics/README.md).
/// Set it to 1 and refit the correctives (`make facegen`) once the
/// corrective channels can follow a person's face.
inline constexpr float kPersonCourseVariation = 0.0f;
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

/// How far a muscle pair's course may move at scale 1, millimetres in the
/// face plane (x lateral, y up), for a typical person: origin and
/// insertion, each axis drawn uniform within +- this.
struct CourseSpread {
  glm::vec2 origin_mm{0.0f};
  glm::vec2 insertion_mm{0.0f};
};
/// Pair `pair` (0 .. 20, facial_muscle_definitions() order); zero for the
/// sphincters and the jaw muscles.
CourseSpread course_spread(std::size_t pair);
/// Largest share of the pair's spread one side moves besides.
inline constexpr float kSideCourseShare = 0.25f;
/// The share of hemifaces with a bifid zygomaticus major (Pessa et al.
/// 1998, Clin. Anat.: 34 %, 17 of 50).
inline constexpr float kBifidShare = 0.34f;
/// How far below the superior bundle's insertion (above the mouth's
/// corner) the inferior bundle of a bifid zygomaticus major inserts (below
/// it), mm at scale 1: the two bundles, 7.2 and 6.1 mm wide (Stoltidou,
/// Dimitrakopoulos, Pateraki, Koebke & Dionyssopoulos 2011, Can. J. Plast.
/// Surg. 19A), side by side. Each bundle takes half the muscle's pull.
inline constexpr float kBifidDropMm = 7.0f;

/// One muscle's course in one person, model units in the face plane, for
/// its own side (a right-side muscle's x is already mirrored): how far its
/// origin and insertion anchors move, and for a bifid zygomaticus major how
/// far below the insertion its inferior bundle inserts (0: a single belly).
struct CourseShift {
  glm::vec2 origin{0.0f};
  glm::vec2 insertion{0.0f};
  float bifid_drop = 0.0f;
};

/// Per muscle (facial_muscles.hpp order) its course in the person of
/// `seed` (SplitMix64, a stream of its own, so the strength factors of a
/// seed are what they were): each axis scale (s_pair u_pair + s_side
/// u_side), u uniform in [-1, 1), s the pair's course_spread and
/// kSideCourseShare of it; the modiolus muscles share one insertion draw.
/// `scale` is clamped to [0, 1] (the literature's spread is the bound):
/// 0 gives the reference face exactly, 1 a typical person. Every |shift|
/// per axis is at most scale (1 + kSideCourseShare) spread /
/// kMillimetresPerUnit.
std::array<CourseShift, kMuscleCount> muscle_course_shifts(std::uint64_t seed, float scale = 1.0f);

/// Whether the universal expressions need muscle pair `pair` (0 .. 20,
/// facial_muscle_definitions() order) in everyone (Waller et al. 2008).
bool universally_present(std::size_t pair);

}  // namespace fw::physics
