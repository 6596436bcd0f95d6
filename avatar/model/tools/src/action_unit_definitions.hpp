#pragma once
// The geometric definitions of FACS action units on the generic face: each
// unit is a few handles (a point that moves by a displacement, with a radius
// of influence) and the regions it may move. The physics face later
// replaces the vertex part with physics-synthesised morphs.
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "fw/codec/face_params.hpp"
#include "fw/model/generic_face.hpp"

namespace fw::facegen {

struct Handle {
  int landmark = -1;                ///< the handle sits on this landmark, or
  glm::vec2 point{0.0f};            ///< at this point when landmark < 0
  glm::vec3 displacement{0.0f};     ///< at full intensity, model units (1 = 63 mm)
  float radius = 0.2f;              ///< influence falls to 0 here, model units
};

/// A jaw rotation (AU 26, 27): vertices below the lips turn about the
/// hinge axis through `hinge` (parallel to x) by `angle_rad`, fully below
/// `full_below_y`, fading out up to `none_above_y`.
struct JawRotation {
  float angle_rad = 0;
  glm::vec3 hinge{0.0f, -0.25f, 0.3f};
  float full_below_y = -1.2f, none_above_y = -1.03f;
};

struct ActionUnitDefinition {
  std::vector<Handle> handles;           ///< for the person's left side, or midline
  std::optional<JawRotation> jaw;
  std::vector<model::FaceRegion> regions;  ///< regions it may move (left side; mirrored for right)
  /// Share of the motion done by moving the mesh; the rest slides the
  /// texture over it (the expressive-textures way, for brows and forehead).
  float mesh_share = 1.0f;
};

/// The definition of FACS action unit `au` (one of codec::kActionUnits).
ActionUnitDefinition action_unit_definition(int au);

}  // namespace fw::facegen
