#pragma once
// The mouth as a viewer sees it: the generic face (the one every avatar is
// fitted from) deformed by action-unit targets as every client rebuilds it
// (model::reconstruct_face), and the gap between the midpoints of the inner
// lips (landmarks 62 and 66), in millimetres. At rest the face has a 1 mm
// slit; lips pressed together (AU 24) overlap there, which is no opening: 0.
#include <algorithm>

#include "fw/codec/face_params.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/speech/au_targets.hpp"

namespace fw::test {

class GenericMouth {
 public:
  float gap_mm(const speech::AuTargets& targets) const {
    codec::FaceParams params;
    params.au = targets;
    const model::FaceShape shape = model::reconstruct_face(avatar_, params);
    const auto& v = avatar_.face.landmark_vertices;
    return std::max(0.0f, (shape.positions[v[62]].y - shape.positions[v[66]].y) * model::kMillimetresPerUnit);
  }

 private:
  model::AvatarModel avatar_ = model::generic_avatar_model();
};

}  // namespace fw::test
