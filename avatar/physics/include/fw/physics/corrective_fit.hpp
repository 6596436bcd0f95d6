#pragma once
// The physics face's corrective basis: what the action units leave of the
// simulated skin over a corpus of behaviour (behaviour_corpus.hpp), as a
// handful of principal components. The corpus is simulated as a room
// simulates its faces (projective dynamics, one 30 Hz step a frame, measured
// every frame); each frame's residual is the skin's displacement minus what
// a client rebuilds from the measured AU weights (the asset's morphs), and
// the components are the leading eigenvectors of the residuals' second
// moment (uncentred PCA: the neutral face has no residual, and a weight of 0
// must rebuild the AUs alone). Each is scaled so that the weights [-1,1]
// cover the fitting corpus to its 99.9th percentile (fewer frames clamped,
// for steps on the wire a little coarser). facewire-correctives
// writes them into the asset; the tests and `facewire-bench sim` use the
// same recording to measure what they buy.
#include <array>
#include <cstddef>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/behaviour_corpus.hpp"
#include "fw/physics/face_simulation.hpp"

namespace fw::physics {

class FacePool;

/// A corpus simulated frame by frame: the skin and what measure() made of it.
struct CorpusRecording {
  std::size_t vertex_count = 0;
  std::vector<float> displacement;  ///< frames x 3 #V, the skin's displacement from rest, model units
  std::vector<AuFrame> targets;     ///< the corpus frame that drove each
  std::vector<FaceMeasurement> measured;
  /// Where each sequence's frames begin (and the end): sequences start at rest.
  std::vector<std::size_t> sequence_start;
  std::size_t frame_count() const { return measured.size(); }
};

/// The people a corpus is recorded on (their muscles' variation seeds):
/// the fitting corpus on people kFittingFirstSeed on, held-out behaviour on
/// people no fit has seen, kHeldOutFirstSeed on, so that what is held out
/// is the faces as well as the behaviour (rooms hold people the fit never met).
inline constexpr std::uint64_t kFittingFirstSeed = 1;
inline constexpr std::uint64_t kHeldOutFirstSeed = 1001;

/// Simulates every sequence of `corpus` on `face` (a fresh face each, at
/// rest, with the muscle variation of person first_seed + its index, as
/// rooms give every face its own), one step of kCorpusFrameS a frame with
/// the head turning as the sequence says, measured against the face's
/// action units and its corrective components (if it has any).
/// @param[in] pool  threads to spread the sequences over (null: this thread)
CorpusRecording record_corpus(const model::GenericFace& face, const BehaviourCorpus& corpus,
                              Solver solver = Solver::projective, FacePool* pool = nullptr,
                              std::uint64_t first_seed = kFittingFirstSeed);

/// Fits at most `count` corrective components on `recording` of `face`:
/// fewer if the residual has fewer directions that carry anything. Vertex
/// displacements under `zero_below` (model units) are written as 0.
std::vector<model::Morph> fit_correctives(const model::GenericFace& face, const CorpusRecording& recording,
                                          std::size_t count = codec::kCorrectiveCount, float percentile = 0.999f,
                                          float zero_below = 1e-4f);

/// The RMS (mm, over the skin vertices and the frames) of the recorded
/// skin against what a client rebuilds from the measured weights: the AU
/// morphs alone, and with the corrective components at their weights.
struct CorrectiveErrors {
  double without_mm = 0;
  double with_mm = 0;
  double cut() const { return without_mm > 0 ? with_mm / without_mm : 0.0; }
};
CorrectiveErrors corrective_errors(const model::GenericFace& face, const CorpusRecording& recording);

}  // namespace fw::physics
