#pragma once
// The eye socket behind each eye hole.
//
// The eyeball sits as far forward as a closed lid lets it (facegen's
// build_eyes): behind the hole's corners, not wrapped by the lids as a real
// globe is. Turned 30 degrees and more, a line of sight through the hole's
// outer part passes beside the eyeball and, with nothing behind it, met
// the head shell's inside texture: a dark wedge in the eye, black at 60
// degrees, the first thing one saw of a turned face. The socket is a
// closed sphere about the eyeball's centre that holds the whole hole, drawn
// from the inside only (its far wall) and only within the hole: every line
// of sight through the hole meets the eyeball or the socket's wall, which
// shows the white of the eye as in the lids' shadow, as the conjunctiva
// folding back into the corners reads.
#include "fw/model/generic_face.hpp"

namespace fw::model {

/// The socket of `face`'s eye on `side` (0 right, 1 left) as the face is
/// (a fitted face's hole has the person's shape): a sphere about the
/// eyeball's centre reaching a margin past the hole's farthest vertex, its
/// triangles facing out (a renderer culls the front faces to show the far
/// wall), its uvs in EyeLayer's polar mapping as the eyeball's, kept off
/// the iris: it continues the eyeball's white.
Mesh eye_socket_mesh(const GenericFace& face, std::size_t side);

/// The socket's radius for `face`'s eye on `side`: what eye_socket_mesh
/// builds (the tests check the hole against it).
float eye_socket_radius(const GenericFace& face, std::size_t side);

}  // namespace fw::model
