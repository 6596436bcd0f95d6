#pragma once
// The projective-dynamics step (Bouaziz et al. 2014, Algorithm 1) of one
// face or of many faces of one tissue model at once: implicit Euler,
// minimised by a few alternations of a local step (every constraint
// projects the current positions, each face on its own) and a global step
// (one sparse solve with the model's factored matrix, the faces'
// right-hand sides interleaved so that the solve runs across them).
// Muscles and gravity are external forces; the skull is a projection after
// the step; the bone layer and the held outline are prescribed positions.
// No mass scaling, no speed limit, no drag of the world: the step is stable
// at any length. The damping is Rayleigh's (projective_system.cpp) and
// each node's bond to its bone, the material's bone_damping.
#include <cstddef>
#include <span>

#include "fw/physics/face_simulation.hpp"

namespace fw::physics {

/// The model whose factorisations a face's steps solve with: faces with the
/// same one (every avatar's fitted face shares the generic face's,
/// TissueModel::projective_reference) go in one batch.
inline const TissueModel* factor_owner(const FaceSimulation& face) {
  const TissueModel& m = face.model();
  return m.projective_reference ? m.projective_reference.get() : &m;
}

class ProjectiveStepper {
 public:
  /// The longest sub-step: the tissue is stable at any length, but implicit
  /// Euler with one local/global pass per step damps and slows it the more
  /// the longer the step is. At one 33 ms step a frame the face was 0.172 mm
  /// RMS from the mass-spring reference over the held-out corpus, and AU 12
  /// took 245 ms to half its travel (mass-spring 125). Two steps of 17 ms
  /// are 0.089 mm from it and take 190 ms (README, "The projective
  /// solver"); 17.5 ms keeps a late 30 Hz frame (35 ms) at two steps.
  static constexpr double kLongestStepS = 0.0175;
  /// The step the factorisations' grid of step lengths passes through: a
  /// 30 Hz frame's half.
  static constexpr double kFrameStepS = 1.0 / 60.0;
  /// Local/global alternations per sub-step. One: each step starts from
  /// where the face is going (x + h v), so a face held by its muscles ends
  /// at the exact equilibrium however few there are, and a moving face lags
  /// it by a little (README, "The projective solver"). Two cost 1.6 times
  /// as much and come less near the reference than two steps of half the
  /// length.
  static constexpr int kIterations = 1;

  /// Steps `faces` by `dt_seconds` as FaceSimulation::step does, those of one
  /// factor_owner() and with the same sub-steps together, up to
  /// detail::kMaxBatchFaces per solve. Every face must use Solver::projective.
  static void step(std::span<FaceSimulation* const> faces, double dt_seconds);
  /// The step the tissue takes for a sub-step of h: h on a grid of 2 %
  /// steps through kFrameStepS, so that frames of slightly varying length share
  /// one factorisation (the matrix holds h) instead of each making its own;
  /// the tissue then runs up to 1 % fast or slow against the clock.
  static float tissue_step(float h);
  /// One sub-step of faces that all share one factor_owner().
  static void substep(std::span<FaceSimulation* const> faces, float h);
};

}  // namespace fw::physics
