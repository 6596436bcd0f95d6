#include "seat_frames_golden.hpp"

#include <vector>

#include <glm/vec3.hpp>

#include "fw/behavior/seat_layout.hpp"

namespace fw::test::web_golden {
namespace {

nlohmann::json vec(glm::vec3 v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json seat_json(const behavior::Seat& s) {
  return {{"origin_mm", vec(s.origin_mm)}, {"facing_yaw_rad", s.facing_yaw_rad}};
}

// Seats of rooms the server lays out, and a few it never would (turned
// round, off the floor), so the port is held on the formula, not the arc.
std::vector<behavior::Seat> seats_to_check() {
  std::vector<behavior::Seat> seats;
  for (int count : {1, 3, 8})
    for (const behavior::Seat& s : behavior::seat_layout(count)) seats.push_back(s);
  seats.push_back({{-250.0f, 40.0f, 900.0f}, 3.14159265f});
  seats.push_back({{1200.0f, -300.0f, -75.5f}, -2.5f});
  seats.push_back({{0.0f, 0.0f, 0.0f}, 1.5707964f});
  return seats;
}

const std::vector<glm::vec3>& points() {
  static const std::vector<glm::vec3> p = {
      {0, 0, 0}, {100, 0, 0}, {0, 100, 0}, {0, 0, 100}, {-63.5f, 41.25f, 600}, {850, -120, -1400}, {-3000, 2000, 3000},
  };
  return p;
}

// Directions through the quadrants, straight up and down, straight back
// (yaw pi), and a zero vector (both angles 0).
const std::vector<glm::vec3>& directions() {
  static const std::vector<glm::vec3> d = {
      {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {0, 0, 0},
      {0.3f, 0.2f, 0.9f}, {-0.3f, -0.2f, 0.9f}, {0.7f, -0.1f, -0.7f}, {-0.7f, 0.5f, -0.2f}, {1e-4f, 0, 1}, {2500, 180, 1100},
  };
  return d;
}

}  // namespace

nlohmann::json seat_frames_golden() {
  const behavior::HeadGeometry& head = behavior::head_geometry();
  nlohmann::json out;
  out["about"] =
      "avatar/behavior/src/seat_layout.cpp (seat_layout, seat_to_room, room_to_seat, direction_angles) in float32, "
      "written by tests/web/golden; web/room/view_geometry.js and gaze_reaim.js (aimAt) must give the same";
  out["eye_mid_mm"] = vec(head.eye_mid_mm);
  nlohmann::json frames = nlohmann::json::array();
  for (const behavior::Seat& seat : seats_to_check()) {
    nlohmann::json cases = nlohmann::json::array();
    for (glm::vec3 p : points())
      cases.push_back({{"point_mm", vec(p)},
                       {"seat_to_room", vec(behavior::seat_to_room(seat, p))},
                       {"room_to_seat", vec(behavior::room_to_seat(seat, p))}});
    // The aim from this seat's eyes at rest at every other seat's eyes: the
    // angles the server's gaze is given for an attention target.
    nlohmann::json aims = nlohmann::json::array();
    for (const behavior::Seat& other : seats_to_check()) {
      const glm::vec3 target = behavior::seat_to_room(other, head.eye_mid_mm);
      const glm::vec3 d = behavior::room_to_seat(seat, target) - head.eye_mid_mm;
      if (d.x * d.x + d.z * d.z < 1.0f) continue;  // the seat itself: no direction
      const behavior::YawPitch a = behavior::direction_angles(d);
      aims.push_back({{"target_mm", vec(target)}, {"yaw_rad", a.yaw_rad}, {"pitch_rad", a.pitch_rad}});
    }
    frames.push_back({{"seat", seat_json(seat)}, {"points", cases}, {"aims", aims}});
  }
  out["frames"] = frames;

  nlohmann::json angles = nlohmann::json::array();
  for (glm::vec3 d : directions()) {
    const behavior::YawPitch a = behavior::direction_angles(d);
    angles.push_back({{"direction", vec(d)}, {"yaw_rad", a.yaw_rad}, {"pitch_rad", a.pitch_rad}});
  }
  out["direction_angles"] = angles;
  return out;
}

}  // namespace fw::test::web_golden
