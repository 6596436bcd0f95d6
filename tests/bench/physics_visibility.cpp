#include "physics_visibility.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "bench_failure.hpp"
#include "bench_rounding.hpp"
#include "kinematic_track.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/physics/corrective_fit.hpp"
#include "fw/physics/face_pool.hpp"

namespace fw::bench {
namespace {

double squared_distance(const model::FaceShape& a, const model::FaceShape& b) {
  double sum = 0.0;
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    const glm::vec3 d = a.positions[v] - b.positions[v];
    sum += double(glm::dot(d, d));
  }
  return sum;
}

// Frame `f` of a recording's skin: `rest` moved by it, in a copy of `like`.
model::FaceShape simulated_skin(const model::FaceShape& like, const std::vector<glm::vec3>& rest,
                                const physics::CorpusRecording& recording, std::size_t f) {
  model::FaceShape skin = like;
  const float* moved = recording.displacement.data() + f * 3 * recording.vertex_count;
  for (std::size_t v = 0; v < recording.vertex_count; ++v)
    skin.positions[v] = rest[v] + glm::vec3(moved[3 * v], moved[3 * v + 1], moved[3 * v + 2]);
  return skin;
}

}  // namespace

nlohmann::json physics_visibility(const std::string& corpus_path) {
  physics::BehaviourCorpus corpus;
  std::string error;
  if (!physics::load_behaviour_corpus(corpus_path, corpus, error)) fail_bench("sim", error);
  const model::AvatarModel avatar = model::generic_avatar_model();
  physics::FacePool pool;
  const physics::CorpusRecording recording =
      physics::record_corpus(avatar.face, corpus, physics::Solver::projective, &pool, physics::kHeldOutFirstSeed);
  // The mass-spring solver at its stable step is the reference the
  // projective one trades accuracy against for speed (physics README,
  // "The projective solver").
  const physics::CorpusRecording reference =
      physics::record_corpus(avatar.face, corpus, physics::Solver::mass_spring, &pool, physics::kHeldOutFirstSeed);
  // The simulated skin itself against the kinematic face: what a perfect
  // corrective basis would show a viewer.
  const std::vector<glm::vec3>& rest = avatar.face.skin.positions;
  double with = 0.0, without = 0.0, skin = 0.0, reference_skin = 0.0, projective_vs_reference = 0.0;
  for (std::size_t s = 0; s + 1 < recording.sequence_start.size(); ++s) {
    KinematicTrack kinematic;
    for (std::size_t f = recording.sequence_start[s]; f < recording.sequence_start[s + 1]; ++f) {
      kinematic.follow(recording.targets[f], physics::kCorpusFrameS);
      codec::FaceParams k, p;
      k.au = kinematic.weights();
      p.au = recording.measured[f].action_units;
      const model::FaceShape kinematic_face = model::reconstruct_face(avatar, k);
      without += squared_distance(model::reconstruct_face(avatar, p), kinematic_face);
      p.corrective = recording.measured[f].corrective;
      with += squared_distance(model::reconstruct_face(avatar, p), kinematic_face);
      const model::FaceShape simulated = simulated_skin(kinematic_face, rest, recording, f);
      const model::FaceShape simulated_reference = simulated_skin(kinematic_face, rest, reference, f);
      skin += squared_distance(simulated, kinematic_face);
      reference_skin += squared_distance(simulated_reference, kinematic_face);
      projective_vs_reference += squared_distance(simulated, simulated_reference);
    }
  }
  const double samples = double(recording.frame_count()) * double(recording.vertex_count);
  const auto mm = [&](double sum) { return samples > 0 ? std::sqrt(sum / samples) * model::kMillimetresPerUnit : 0.0; };
  const physics::CorrectiveErrors errors = physics::corrective_errors(avatar.face, recording);
  return {
      {"corpus_frames", recording.frame_count()},
      {"corrective_components", avatar.face.correctives.size()},
      {"physics_vs_kinematic_mm", rounded(mm(with))},
      {"physics_vs_kinematic_mm_without_correctives", rounded(mm(without))},
      {"simulated_skin_vs_kinematic_mm", rounded(mm(skin))},
      {"reference_skin_vs_kinematic_mm", rounded(mm(reference_skin))},
      {"projective_vs_reference_mm", rounded(mm(projective_vs_reference))},
      {"corrective_residual_mm_without", rounded(errors.without_mm)},
      {"corrective_residual_mm_with", rounded(errors.with_mm)},
      {"corrective_error_cut", rounded(errors.cut())},
  };
}

}  // namespace fw::bench
