#pragma once
// The XPBD solver's muscles: each muscle as particles along its action line,
// the tissue it moves tied to them (the PBD face paper's muscle model: a
// muscle contracts along its action line, sampled by particles, and carries
// the tissue attached to it).
//
// A linear muscle's particles run from its bony origin to the far end of its
// attachments; at full contraction each has moved toward the origin by
// kFullShortening of its distance from it (uniform strain: the origin stays,
// the insertion end moves most). A sphincter's particles ring its centre,
// one per sector of its attachments; at full contraction the ring has
// shrunk toward the centre by the sphincter's per-axis weights. Particles
// are kinematic and ride the bone under them as the jaw turns. Each
// attached node is tied to the point of the contracted action line it lies
// beside, keeping its rest offset; the tie's stiffness is the activation
// times a stiffness with which it pulls with the muscle's strength (the
// mass-spring solver's force) while the tissue has not moved, less as it
// follows (xpbd_step.cpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "fw/physics/facial_muscles.hpp"

namespace fw::physics {

struct TissueModel;
struct MuscleCourse;

struct MuscleParticles {
  // Per particle.
  std::vector<glm::vec3> rest;        ///< model units
  std::vector<std::uint16_t> column;  ///< the skin vertex whose bone it rides and along whose skull it moves
  std::vector<std::uint8_t> muscle;   ///< facial_muscles.hpp order
  /// Per muscle attachment (muscle by muscle, muscle_attachments() order
  /// within each; the model's attach_node order for its own): the node lies
  /// beside (1 - share) particle[first] + share particle[first + 1] (a
  /// sphincter's share is 0), share in 255ths, keeping its rest offset.
  std::vector<std::uint16_t> tie_first;
  std::vector<std::uint8_t> tie_share;

  std::size_t particle_count() const { return rest.size(); }
  std::size_t memory_bytes() const;
};

/// Each of `particles`' moves at activation 1: toward its muscle's
/// `origin` by kFullShortening of its distance (linear), toward the centre
/// weighted per axis (sphincter), along the skull under it. #particles.
void full_contraction(const TissueModel& model, const MuscleParticles& particles,
                      const std::array<glm::vec3, kMuscleCount>& origin, std::vector<glm::vec3>& move);

/// Each tie's stiffness per unit of its muscle's strength (times the
/// strength and the activation, force per model unit): it pulls with
/// strength x attachment `weight`, the mass-spring solver's force, while
/// the node has not moved. `move` is full_contraction's.
float tie_stiffness_per_strength(const MuscleParticles& particles, const std::vector<glm::vec3>& move, std::size_t tie,
                                 float weight);

/// Lays the particles and ties of every muscle of `model` (its muscles,
/// attachments and rest shape must be built), or of one face's `course`
/// of them (muscle_course.hpp).
MuscleParticles build_muscle_particles(const TissueModel& model, const MuscleCourse* course = nullptr);

}  // namespace fw::physics
