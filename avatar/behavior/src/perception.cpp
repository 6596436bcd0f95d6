#include "fw/behavior/perception.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace fw::behavior {

std::vector<PerceivedFace> perceive(const FaceSnapshot& self, const std::vector<FaceSnapshot>& room) {
  std::vector<PerceivedFace> seen;
  const glm::vec3 my_eyes = room_to_seat(self.seat, self.eye_mid_room_mm);
  for (const FaceSnapshot& other : room) {
    if (other.id == self.id) continue;
    PerceivedFace p;
    p.id = other.id;
    p.eyes_seat_mm = room_to_seat(self.seat, other.eye_mid_room_mm);
    p.mouth_seat_mm = room_to_seat(self.seat, other.mouth_room_mm);
    p.direction = direction_angles(p.eyes_seat_mm - my_eyes);
    if (std::abs(p.direction.yaw_rad - self.head_yaw_rad) > kFieldOfViewHalfRad) continue;
    p.distance_mm = glm::length(p.eyes_seat_mm - my_eyes);
    p.looking_at = other.looking_at;
    p.looks_at_me = other.looking_at == self.id;
    p.emotion = other.emotion;
    p.emotion_template = other.emotion_template;
    p.speaking_since_s = other.speaking_since_s;
    seen.push_back(p);
  }
  std::sort(seen.begin(), seen.end(), [](const PerceivedFace& a, const PerceivedFace& b) {
    return a.distance_mm < b.distance_mm || (a.distance_mm == b.distance_mm && a.id < b.id);
  });
  return seen;
}

std::optional<FaceId> face_on_gaze(FaceId self, glm::vec3 origin, glm::vec3 direction,
                                   const std::vector<FaceSnapshot>& room) {
  std::optional<FaceId> best;
  float best_angle = kAttendConeRad;
  const auto angle_to = [&](glm::vec3 point) {
    const glm::vec3 to = point - origin;
    const float len = glm::length(to);
    if (len <= 0) return 10.0f;
    return std::acos(std::clamp(glm::dot(to / len, glm::normalize(direction)), -1.0f, 1.0f));
  };
  for (const FaceSnapshot& other : room) {
    if (other.id == self) continue;
    // Gaze on the eyes, the nose or the mouth rests on the face: eyes scan
    // between them (face_scan.hpp). A near face's features lie beyond the
    // cone; its area, seen from here, is wider.
    const glm::vec3 centre = 0.5f * (other.eye_mid_room_mm + other.mouth_room_mm);
    const float distance = glm::length(centre - origin);
    const float area = distance > 0 ? std::atan(kFaceAreaRadiusMm / distance) : kAttendConeRad;
    const float angle = std::min({angle_to(other.eye_mid_room_mm), angle_to(other.mouth_room_mm),
                                  angle_to(centre) * kAttendConeRad / std::max(area, kAttendConeRad)});
    if (angle <= best_angle) {
      best_angle = angle;
      best = other.id;
    }
  }
  return best;
}

int attending_count(FaceId id, const std::vector<FaceSnapshot>& room) {
  return static_cast<int>(std::count_if(room.begin(), room.end(),
                                        [&](const FaceSnapshot& s) { return s.id != id && s.looking_at == id; }));
}

}  // namespace fw::behavior
