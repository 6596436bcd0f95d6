#pragma once
// Distortion as a viewer meets it: how far the vertices of the face mesh
// land from where the original parameters put them, in millimetres of a
// face with a 63 mm inter-ocular distance. Both faces are rebuilt through
// avatar/model (action units and lids) and posed like the renderer poses
// them (head rotation about the neck pivot, head translation).
#include <cstdint>

#include "fw/codec/face_params.hpp"
#include "fw/model/avatar_model.hpp"

namespace fw::bench {

inline constexpr double kInterOcularMm = 63.0;

class VertexError {
 public:
  explicit VertexError(const model::AvatarModel& avatar) : avatar_(avatar) {}

  /// Adds one frame: every skin vertex's distance between the two poses.
  void add(const codec::FaceParams& original, const codec::FaceParams& shown);

  double rms_mm() const;
  double max_mm() const { return max_mm_; }

 private:
  const model::AvatarModel& avatar_;
  double sum_sq_mm_ = 0, max_mm_ = 0;
  std::uint64_t samples_ = 0;
};

}  // namespace fw::bench
