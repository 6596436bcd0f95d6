#include "redefined_units.hpp"

#include <set>

#include "fw/model/generic_face.hpp"

namespace fw::server {
namespace {

/// The action units `morphs` redefines (a bilateral unit counts once).
std::size_t redefined_units(const model::UnitMorphSet& morphs) {
  std::set<int> aus;
  for (const auto& [channel, morph] : morphs) aus.insert(codec::kAuChannels[channel].au);
  return aus.size();
}

}  // namespace

std::string RedefinedUnits::apply(const std::vector<behavior::UnitDefinition>& units) {
  model::UnitMorphSet next = morphs_;
  for (const behavior::UnitDefinition& unit : units) {
    for (std::size_t c = 0; c < codec::kAuChannelCount; ++c)
      if (codec::kAuChannels[c].au == unit.au) next.erase(c);
    for (const auto& [channel, morph] : unit.morphs) next[channel] = model::as_carried(channel, morph);
  }
  if (const std::size_t count = redefined_units(next); count > behavior::kMaxRedefinedUnitsPerAvatar)
    return "your avatar would have " + std::to_string(count) + " redefined action units; at most " +
           std::to_string(behavior::kMaxRedefinedUnitsPerAvatar) +
           " at once: restore one first (AU n with no displacements, then end)";
  take(std::move(next));
  ++version_;
  return {};
}

std::string RedefinedUnits::restore(const codec::UnitMorphs& message) {
  std::string error;
  auto morphs = model::unit_morph_set(message, model::generic_face().skin.positions.size(), error);
  if (!morphs) return error;
  if (const std::size_t units = redefined_units(*morphs); units > behavior::kMaxRedefinedUnitsPerAvatar)
    return std::to_string(units) + " redefined action units; an avatar holds at most " +
           std::to_string(behavior::kMaxRedefinedUnitsPerAvatar);
  take(std::move(*morphs));
  version_ = message.version;
  return {};
}

void RedefinedUnits::take(model::UnitMorphSet morphs) {
  morphs_ = std::move(morphs);
  basis_.reset();
  if (morphs_.empty()) return;
  const model::GenericFace& face = model::generic_face();
  const std::size_t length = 3 * face.skin.positions.size();
  std::vector<float> rows(codec::kAuChannelCount * length);
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const auto own = morphs_.find(c);
    const model::Morph& morph = own != morphs_.end() ? own->second : face.action_units[c];
    for (std::size_t v = 0; v < morph.vertex_delta.size(); ++v)
      for (int k = 0; k < 3; ++k) rows[c * length + 3 * v + static_cast<std::size_t>(k)] = morph.vertex_delta[v][k];
  }
  basis_ = physics::AuBasis::from_rows(rows, length);
}

codec::UnitMorphs RedefinedUnits::message(std::uint32_t avatar) const {
  codec::UnitMorphs message{avatar, version_, {}};
  for (const auto& [channel, morph] : morphs_) message.units.push_back(model::unit_morph_message(channel, morph));
  return message;
}

RedefinedUnits::Weights RedefinedUnits::physics_targets(Weights targets) const {
  for (const auto& [channel, morph] : morphs_) targets[channel] = 0;
  return targets;
}

void RedefinedUnits::measure(const physics::FaceSimulation& simulation, const Weights& own, Weights& weights) const {
  if (!basis_) return;
  const physics::TissueModel& m = simulation.model();
  const std::size_t n = m.vertex_count;
  std::vector<float> d(3 * n);
  for (std::size_t v = 0; v < n; ++v) {
    const glm::vec3 p = simulation.node_position(v);
    d[3 * v + 0] = p.x - m.rest_x[v];
    d[3 * v + 1] = p.y - m.rest_y[v];
    d[3 * v + 2] = p.z - m.rest_z[v];
  }
  for (const auto& [channel, morph] : morphs_)
    for (std::size_t v = 0; v < n && v < morph.vertex_delta.size(); ++v)
      for (int k = 0; k < 3; ++k) d[3 * v + static_cast<std::size_t>(k)] += own[channel] * morph.vertex_delta[v][k];
  physics::project_onto_basis(*basis_, d, weights);
}

}  // namespace fw::server
