#pragma once
// Reading and writing the generic face asset (JSON, format described in
// avatar/model/README.md). Reading validates the whole face, so a damaged
// file is an error with a message, never a crash or a half-loaded face.
#include <string>
#include <string_view>
#include <vector>

#include "fw/model/generic_face.hpp"

namespace fw::model {

/// Serialises `face` deterministically: the same face gives the same bytes,
/// numbers rounded to 6 significant digits, one vertex or triangle a line.
std::string serialize_face_asset(const GenericFace& face);

/// Parses and validates an asset.
/// @param[in]  json   the file's contents
/// @param[out] face   the face, untouched on failure
/// @param[out] error  what is wrong, on failure
/// @return true on success
bool parse_face_asset(std::string_view json, GenericFace& face, std::string& error);

/// Every problem found in `face`: indices out of range, degenerate or flipped
/// skin triangles, inconsistent winding or non-manifold edges, landmarks not
/// anchored to distinct vertices, triangles without a region, missing or
/// wrong holes, empty layers. Empty when the face is sound.
std::vector<std::string> validate_generic_face(const GenericFace& face);

}  // namespace fw::model
