#pragma once
// The head behind the generic face: scalp, sides with ears, jaw and neck.
// Private to the generator.
#include "fw/model/generic_face.hpp"

namespace fw::facegen {

/// A closed low-polygon head around the face's `skin`, its front set back
/// behind the face so the face overlaps it, meeting the face along its rim
/// just behind it, with uvs in `frame`.
model::HeadShell build_head_shell(const model::Mesh& skin, const model::TextureFrame& frame);

}  // namespace fw::facegen
