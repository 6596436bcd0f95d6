#include "preview_surface.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/model/unit_morphs.hpp"

namespace fw::server {
codec::PreviewSurface preview_surface(std::uint32_t avatar, const physics::FaceSimulation& simulation,
                                      const RedefinedUnits::Weights& weights, const RedefinedUnits& units,
                                      const RedefinedUnits::Weights& own) {
  const physics::TissueModel& m = simulation.model();
  const std::size_t n = std::min<std::size_t>(m.vertex_count, codec::kMaxUnitMorphMoves);
  assert(m.vertex_count == model::generic_face().skin.positions.size());
  constexpr float kMinUnits = kPreviewSurfaceMinMm / model::kMillimetresPerUnit;
  codec::PreviewSurface out{avatar, {}};
  for (std::size_t v = 0; v < n; ++v) {
    glm::vec3 d = simulation.node_position(v) - glm::vec3(m.rest_x[v], m.rest_y[v], m.rest_z[v]);
    // What the client rebuilds: every channel's morph at its weight (the
    // avatar's own cloned morphs, which its simulation measures against),
    // a redefined channel's own morph; a redefined unit's morph moves the
    // face beside the physics at its own track (redefined_units.hpp).
    for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
      const auto redefined = units.morphs().find(c);
      if (redefined == units.morphs().end()) {
        const float weight = weights[c];
        if (weight != 0.0f)
          d -= weight * glm::vec3(m.basis.at(c, 3 * v), m.basis.at(c, 3 * v + 1), m.basis.at(c, 3 * v + 2));
        continue;
      }
      const model::Morph& morph = redefined->second;
      if (v >= morph.vertex_delta.size()) continue;
      d -= (weights[c] - own[c]) * morph.vertex_delta[v];
    }
    if (glm::length(d) < kMinUnits) continue;
    out.moves.push_back({static_cast<std::uint32_t>(v), {model::unit_morph_steps(d.x), model::unit_morph_steps(d.y), model::unit_morph_steps(d.z)}});
  }
  return out;
}

}  // namespace fw::server
