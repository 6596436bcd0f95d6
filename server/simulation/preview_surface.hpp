#pragma once
// What a face-lab preview's page is sent beside its frames (PROTOCOL.md
// 5.18): the part of the simulated skin's displacement that the frames'
// action units do not rebuild. Frames carry only the surface's projection on
// the action units, so a muscle pulling where no unit has a shape (or past
// what a unit's shape says) would not show; the page adds this residual to
// the face it rebuilds and so draws the simulated surface itself.
//
// Per skin vertex of the generic face (every avatar's physics face is the
// generic face's, room_simulation.cpp), in its vertex order and the unit
// morphs' step (1/4096 model unit); a vertex whose residual is under
// kPreviewSurfaceMinMm is left out (too small to see on a page, and it
// keeps a face at rest from sending noise).
#include <cstdint>

#include "fw/codec/messages.hpp"
#include "fw/physics/face_simulation.hpp"
#include "redefined_units.hpp"

namespace fw::server {

/// Residuals under this are left out, millimetres (a twentieth of a
/// millimetre: under a pixel of a face drawn 500 pixels wide).
inline constexpr float kPreviewSurfaceMinMm = 0.05f;

/// The residual of `simulation`'s skin after its frames' action units.
/// @param[in] avatar     the preview's avatar id, for the message
/// @param[in] weights    the AU weights its frames carry from the physics face (before speech and plateau motion)
/// @param[in] units      its person's redefined units (their morphs rebuild those channels)
/// @param[in] own        each redefined unit's own track, 0 .. 1 (RedefinedUnits::measure)
codec::PreviewSurface preview_surface(std::uint32_t avatar, const physics::FaceSimulation& simulation,
                                      const RedefinedUnits::Weights& weights, const RedefinedUnits& units,
                                      const RedefinedUnits::Weights& own);

}  // namespace fw::server
