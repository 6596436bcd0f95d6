#include "fw/physics/synthesize_action_units.hpp"

#include <glm/geometric.hpp>

#include "fw/physics/face_pool.hpp"
#include "fw/physics/face_simulation.hpp"

namespace fw::physics {

std::array<std::vector<glm::vec3>, codec::kAuChannelCount> synthesize_action_units(
    const model::GenericFace& face, const BasisSynthesisOptions& options, FacePool* pool) {
  const std::shared_ptr<const TissueModel> tissue = build_tissue_model(face, face.action_units);
  std::array<std::vector<glm::vec3>, codec::kAuChannelCount> out;
  auto synthesize = [&](std::size_t channel) {
    SimulationOptions sim_options;
    sim_options.solver = Solver::projective;
    sim_options.individual_variation = 0.0f;
    FaceSimulation sim(tissue, sim_options);
    std::array<float, codec::kAuChannelCount> targets{};
    targets[channel] = 1.0f;
    sim.set_action_units(targets);
    for (double t = 0.0; t < options.max_seconds && !sim.at_rest(); t += options.frame_s) sim.step(options.frame_s);
    std::vector<glm::vec3> displacement = sim.surface();
    for (std::size_t v = 0; v < displacement.size(); ++v) {
      displacement[v] -= face.skin.positions[v];
      if (glm::length(displacement[v]) < options.zero_below) displacement[v] = glm::vec3(0.0f);
    }
    out[channel] = std::move(displacement);
  };
  if (pool) pool->for_each(codec::kAuChannelCount, synthesize);
  else
    for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) synthesize(c);
  return out;
}

void replace_action_unit_displacements(
    model::GenericFace& face, const std::array<std::vector<glm::vec3>, codec::kAuChannelCount>& displacements) {
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    model::Morph& morph = face.action_units[c];
    morph.vertex_delta = displacements[c];
    morph.uv_delta.resize(morph.vertex_delta.size(), glm::vec2(0.0f));
  }
  // Fitted to what the replaced units left: facewire-correctives fits them again.
  face.correctives.clear();
}

}  // namespace fw::physics
