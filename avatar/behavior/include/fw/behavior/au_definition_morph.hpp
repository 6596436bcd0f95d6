#pragma once
// An action unit redefined in a face script (control-point displacements per
// region, the syntax-directed paper's form) turned into a morph of the
// generic face, to replace that unit's geometric definition.
#include <optional>
#include <string>

#include "fw/model/generic_face.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::behavior {

/// A region's control points are its vertices, numbered across the face
/// from the viewer's left to right (top to bottom where x ties), so that
/// "Brow 3" is the fourth brow point from the left end of the brows.
std::vector<std::uint32_t> region_control_points(const model::GenericFace& face,
                                                 const std::vector<std::string>& regions);

/// The morph a definition describes: each control point moves by its
/// displacement times `model_units_per_unit`, and the skin of the named
/// regions around it follows with a smooth falloff (radius 0.15 units).
/// The default scale reads the displacements in units of a face 200 wide
/// (the generic face is about 2.3 units across).
/// @return nullopt and `error` if a region or control point does not exist
std::optional<model::Morph> au_definition_morph(const script::AuDefinition& definition,
                                                const model::GenericFace& face, std::string& error,
                                                float model_units_per_unit = 2.29f / 200.0f);

}  // namespace fw::behavior
