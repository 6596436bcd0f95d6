#include "fw/behavior/face_scan.hpp"

#include <algorithm>
#include <cmath>

namespace fw::behavior {

FaceScan::FaceScan(std::uint64_t seed) : rng_(seed) {}

FacePoint FaceScan::step(double now_s, std::optional<FaceId> attended, bool attended_speaks) {
  std::uniform_real_distribution<double> unit(0, 1);
  const auto either_eye = [&] { return unit(rng_) < 0.5 ? FacePoint::left_eye : FacePoint::right_eye; };
  const auto fixation = [&] {
    const double d = std::lognormal_distribution<double>(std::log(kFixationS), kFixationSpread)(rng_);
    return std::clamp(d, kShortestS, kLongestS);
  };
  if (attended != face_) {
    face_ = attended;
    point_ = either_eye();
    until_s_ = now_s + fixation();
  } else if (now_s >= until_s_) {
    const double mouth = attended_speaks ? kMouthWhileSpeaking : kMouthOtherwise;
    const double draw = unit(rng_);
    FacePoint next = draw < mouth ? FacePoint::mouth : draw < mouth + kNose ? FacePoint::nose : either_eye();
    // An eye after an eye is the other one: the scan moves.
    if (next == point_) next = next == FacePoint::left_eye ? FacePoint::right_eye : either_eye();
    point_ = next;
    until_s_ = now_s + fixation();
  }
  return point_;
}

glm::vec3 face_point_room(const FaceSnapshot& s, FacePoint p) {
  if (p == FacePoint::mouth) return s.mouth_room_mm;
  if (p == FacePoint::nose) return s.eye_mid_room_mm + 0.55f * (s.mouth_room_mm - s.eye_mid_room_mm);
  // The head's right (its own left eye sits toward +x, as in eye_head.cpp)
  // turned by the head's yaw, then by the seat into the room.
  const float yaw = s.head_yaw_rad;
  const glm::vec3 across_seat{std::cos(yaw), 0.0f, -std::sin(yaw)};
  const glm::vec3 across = seat_to_room(s.seat, across_seat) - seat_to_room(s.seat, glm::vec3(0.0f));
  const float half_interocular = 0.5f * head_geometry().interocular_mm;
  return s.eye_mid_room_mm + (p == FacePoint::left_eye ? half_interocular : -half_interocular) * across;
}

}  // namespace fw::behavior
