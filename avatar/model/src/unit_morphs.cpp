#include "fw/model/unit_morphs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fw/model/motion_cloning.hpp"

namespace fw::model {
namespace {

Morph morph_of(const std::vector<codec::UnitMorphs::Move>& moves, std::size_t vertex_count) {
  Morph morph;
  morph.vertex_delta.assign(vertex_count, glm::vec3(0.0f));
  morph.uv_delta.assign(vertex_count, glm::vec2(0.0f));
  for (const codec::UnitMorphs::Move& move : moves)
    morph.vertex_delta[move.vertex] = glm::vec3(move.delta[0], move.delta[1], move.delta[2]) / codec::kUnitMorphStepsPerUnit;
  return morph;
}

Morph morph_of(const codec::UnitMorphs::Unit& unit, std::size_t vertex_count) { return morph_of(unit.moves, vertex_count); }

}  // namespace

std::int16_t unit_morph_steps(float units) {
  const float steps = std::round(units * codec::kUnitMorphStepsPerUnit);
  return static_cast<std::int16_t>(std::clamp(steps, float(std::numeric_limits<std::int16_t>::min()),
                                              float(std::numeric_limits<std::int16_t>::max())));
}

codec::UnitMorphs::Unit unit_morph_message(std::size_t channel, const Morph& generic) {
  codec::UnitMorphs::Unit unit;
  unit.channel = static_cast<std::uint8_t>(channel);
  for (std::size_t v = 0; v < generic.vertex_delta.size(); ++v) {
    const glm::vec3 d = generic.vertex_delta[v];
    const std::array<std::int16_t, 3> steps{unit_morph_steps(d.x), unit_morph_steps(d.y), unit_morph_steps(d.z)};
    if (steps != std::array<std::int16_t, 3>{}) unit.moves.push_back({static_cast<std::uint32_t>(v), steps});
  }
  return unit;
}

std::optional<UnitMorphSet> unit_morph_set(const codec::UnitMorphs& message, std::size_t vertex_count,
                                           std::string& error) {
  UnitMorphSet set;
  for (const codec::UnitMorphs::Unit& unit : message.units) {
    if (!unit.moves.empty() && unit.moves.back().vertex >= vertex_count) {
      error = "avatar " + std::to_string(message.avatar) + "'s redefined unit moves vertex " +
              std::to_string(unit.moves.back().vertex) + "; the face has " + std::to_string(vertex_count);
      return std::nullopt;
    }
    set[unit.channel] = morph_of(unit, vertex_count);
  }
  return set;
}

Morph as_carried(std::size_t channel, const Morph& generic) {
  return morph_of(unit_morph_message(channel, generic), generic.vertex_delta.size());
}

void set_unit_morphs(AvatarModel& avatar, const GenericFace& generic, const UnitMorphSet& units) {
  for (std::size_t c = 0; c < avatar.morphs.size(); ++c) {
    const auto redefined = units.find(c);
    const Morph& source = redefined != units.end() ? redefined->second : generic.action_units[c];
    avatar.morphs[c] = avatar.jacobians.empty() ? source : clone_morph(source, avatar.jacobians);
  }
}

std::optional<std::vector<glm::vec3>> carried_surface(const AvatarModel& avatar,
                                                      const std::vector<codec::UnitMorphs::Move>& moves,
                                                      std::size_t vertex_count, std::string& error) {
  if (!moves.empty() && moves.back().vertex >= vertex_count) {
    error = "the preview surface moves vertex " + std::to_string(moves.back().vertex) + "; the face has " +
            std::to_string(vertex_count);
    return std::nullopt;
  }
  const Morph generic = morph_of(moves, vertex_count);
  return avatar.jacobians.empty() ? generic.vertex_delta : clone_morph(generic, avatar.jacobians).vertex_delta;
}

}  // namespace fw::model
