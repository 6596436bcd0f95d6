#pragma once
// The depth of a generic adult face, as a smooth function of the frontal
// position. The generic mesh takes its z from here; photo fitting keeps it.
#include <glm/vec2.hpp>

namespace fw::model {

/// Depth (z, toward the viewer) of the face surface at frontal position `p`,
/// both in model units (see landmark_template.hpp). The nose tip is the
/// furthest forward point (about 2.2); the surface curves back toward the
/// ears and over the top of the forehead so that a turned head keeps a
/// head-like silhouette. Defined everywhere; meaningful within |x| < 1.5,
/// -2.2 < y < 1.8.
float face_depth(glm::vec2 p);

}  // namespace fw::model
