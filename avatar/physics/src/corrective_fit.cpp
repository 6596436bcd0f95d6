#include "fw/physics/corrective_fit.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <Eigen/Dense>
#include <glm/geometric.hpp>

#include "fw/model/landmark_template.hpp"
#include "fw/physics/face_pool.hpp"
#include "fw/physics/muscle_variation.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::physics {
namespace {

// Below this share of the leading component's energy a direction is noise
// (float round-off of the simulation), not a shape worth a channel.
constexpr double kNegligibleEnergy = 1e-6;

// `out` (3 #V) = the displacement frame f rebuilt by its AU weights, subtracted
// from the recorded one: what the AUs leave.
void au_residual(const model::GenericFace& face, const CorpusRecording& r, std::size_t f, std::span<double> out) {
  const std::size_t n = r.vertex_count;
  for (std::size_t k = 0; k < 3 * n; ++k) out[k] = r.displacement[f * 3 * n + k];
  const auto& w = r.measured[f].action_units;
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    if (w[c] == 0.0f) continue;
    const auto& delta = face.action_units[c].vertex_delta;
    for (std::size_t v = 0; v < n; ++v)
      for (int a = 0; a < 3; ++a) out[3 * v + a] -= double(w[c]) * delta[v][a];
  }
}

}  // namespace

CorpusRecording record_corpus(const model::GenericFace& face, const BehaviourCorpus& corpus, Solver solver,
                              FacePool* pool, std::uint64_t first_seed) {
  const std::shared_ptr<const TissueModel> tissue = build_tissue_model(face, face.action_units);
  const auto correctives =
      std::make_shared<const CorrectiveBasis>(CorrectiveBasis::from_morphs(face.correctives, tissue->basis));
  CorpusRecording r;
  r.vertex_count = face.skin.positions.size();
  const std::size_t n = r.vertex_count;
  for (const CorpusSequence& s : corpus.sequences) {
    r.sequence_start.push_back(r.targets.size());
    r.targets.insert(r.targets.end(), s.frames.begin(), s.frames.end());
  }
  r.sequence_start.push_back(r.targets.size());
  r.displacement.assign(r.targets.size() * 3 * n, 0.0f);
  r.measured.assign(r.targets.size(), {});
  // Each sequence on its own face, into its own frames: the result does not
  // depend on how the pool spreads them.
  const auto run = [&](std::size_t i) {
    SimulationOptions options;
    options.solver = solver;
    // Each sequence a person's face, as rooms simulate them
    // (server/simulation): muscles of their own strengths and courses.
    options.individual_variation = kPersonVariation;
    options.course_variation = kPersonCourseVariation;
    options.seed = first_seed + i;
    FaceSimulation sim(tissue, options, correctives);
    const CorpusSequence& sequence = corpus.sequences[i];
    for (std::size_t f = r.sequence_start[i]; f < r.sequence_start[i + 1]; ++f) {
      sim.set_action_units(r.targets[f]);
      sim.set_head_pose(sequence.head(f - r.sequence_start[i]));
      sim.step(kCorpusFrameS);
      r.measured[f] = sim.measure();
      for (std::size_t v = 0; v < n; ++v) {
        const glm::vec3 d = sim.node_position(v) - glm::vec3(tissue->rest_x[v], tissue->rest_y[v], tissue->rest_z[v]);
        for (int a = 0; a < 3; ++a) r.displacement[(f * n + v) * 3 + std::size_t(a)] = d[a];
      }
    }
  };
  if (pool) pool->for_each(corpus.sequences.size(), run);
  else
    for (std::size_t i = 0; i < corpus.sequences.size(); ++i) run(i);
  return r;
}

std::vector<model::Morph> fit_correctives(const model::GenericFace& face, const CorpusRecording& recording,
                                          std::size_t count, float percentile, float zero_below) {
  const std::size_t n = recording.vertex_count, frames = recording.frame_count(), dims = 3 * n;
  count = std::min(count, codec::kCorrectiveCount);
  if (frames == 0 || count == 0) return {};
  Eigen::MatrixXd residual(static_cast<Eigen::Index>(frames), static_cast<Eigen::Index>(dims));
  std::vector<double> row(dims);
  for (std::size_t f = 0; f < frames; ++f) {
    au_residual(face, recording, f, row);
    for (std::size_t k = 0; k < dims; ++k) residual(Eigen::Index(f), Eigen::Index(k)) = row[k];
  }
  const Eigen::MatrixXd moment = residual.transpose() * residual;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(moment);
  // Eigen sorts the eigenvalues ascending: the leading components are last.
  const Eigen::Index last = Eigen::Index(dims) - 1;
  const double leading = std::max(eigen.eigenvalues()(last), 0.0);
  std::vector<model::Morph> components;
  for (std::size_t k = 0; k < count; ++k) {
    const Eigen::Index column = last - Eigen::Index(k);
    if (!(leading > 0.0) || eigen.eigenvalues()(column) < kNegligibleEnergy * leading) break;
    Eigen::VectorXd u = eigen.eigenvectors().col(column);
    // An eigenvector's sign is arbitrary: its largest entry is made positive,
    // so that the same residual always gives the same asset.
    Eigen::Index peak = 0;
    u.cwiseAbs().maxCoeff(&peak);
    if (u(peak) < 0) u = -u;
    // Weight of each frame along u, and the scale that puts the chosen
    // percentile of their sizes at 1.
    const Eigen::VectorXd along = residual * u;
    std::vector<double> size(frames);
    for (std::size_t f = 0; f < frames; ++f) size[f] = std::abs(along(Eigen::Index(f)));
    const std::size_t at = std::min(frames - 1, static_cast<std::size_t>(std::floor(percentile * double(frames - 1))));
    std::nth_element(size.begin(), size.begin() + std::ptrdiff_t(at), size.end());
    const double scale = size[at];
    if (!(scale > 0.0)) break;
    model::Morph m;
    m.vertex_delta.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
      const glm::vec3 d(static_cast<float>(scale * u(Eigen::Index(3 * v))), static_cast<float>(scale * u(Eigen::Index(3 * v + 1))),
                        static_cast<float>(scale * u(Eigen::Index(3 * v + 2))));
      m.vertex_delta[v] = glm::length(d) < zero_below ? glm::vec3(0.0f) : d;
    }
    components.push_back(std::move(m));
  }
  return components;
}

CorrectiveErrors corrective_errors(const model::GenericFace& face, const CorpusRecording& recording) {
  const std::size_t n = recording.vertex_count, frames = recording.frame_count();
  std::vector<double> row(3 * n);
  double without = 0.0, with = 0.0;
  for (std::size_t f = 0; f < frames; ++f) {
    au_residual(face, recording, f, row);
    for (double x : row) without += x * x;
    const auto& c = recording.measured[f].corrective;
    for (std::size_t k = 0; k < face.correctives.size(); ++k) {
      if (c[k] == 0.0f) continue;
      const auto& delta = face.correctives[k].vertex_delta;
      for (std::size_t v = 0; v < n; ++v)
        for (int a = 0; a < 3; ++a) row[3 * v + std::size_t(a)] -= double(c[k]) * delta[v][a];
    }
    for (double x : row) with += x * x;
  }
  CorrectiveErrors e;
  if (frames == 0 || n == 0) return e;
  const double count = double(frames) * double(n);
  e.without_mm = std::sqrt(without / count) * model::kMillimetresPerUnit;
  e.with_mm = std::sqrt(with / count) * model::kMillimetresPerUnit;
  return e;
}

}  // namespace fw::physics
