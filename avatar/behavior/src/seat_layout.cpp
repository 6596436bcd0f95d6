#include "fw/behavior/seat_layout.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/model/landmark_template.hpp"

namespace fw::behavior {

namespace {

// Seats evenly on an arc open toward +z, `step` apart on it, neighbours
// kSeatSpacingMm apart; each facing the arc's centre (yaw -phi).
std::vector<Seat> arc_of(int count, float step, float spacing_mm) {
  std::vector<Seat> seats(static_cast<std::size_t>(std::max(count, 0)));
  if (count <= 1) return seats;
  const float radius = 0.5f * spacing_mm / std::sin(0.5f * step);
  const glm::vec3 centre(0.0f, 0.0f, radius);
  for (int i = 0; i < count; ++i) {
    const float phi = (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * step;
    seats[static_cast<std::size_t>(i)].origin_mm = centre + radius * glm::vec3(std::sin(phi), 0.0f, -std::cos(phi));
    seats[static_cast<std::size_t>(i)].facing_yaw_rad = -phi;
  }
  return seats;
}

float wrapped(float a) { return std::remainder(a, 6.2831853f); }

// The yaw (room frame, 0 toward the viewer) of the direction from `from` to `to`.
float yaw_toward(glm::vec3 from, glm::vec3 to) { return std::atan2(to.x - from.x, to.z - from.z); }

}  // namespace

std::vector<Seat> seat_layout(int count, float span_rad) {
  // Why 120 degrees: a seat with partners on both sides turns its head by
  // 90 degrees less half the arc between neighbours to see one, and a
  // seat whose partners all lie to one side would have to turn its back on
  // the viewer to face them. With no face more than 60 degrees from the
  // viewer, spreading the seats over 120 degrees gives the smallest largest
  // head turn toward a partner for every room of 3 to 16 (measured: the
  // table in avatar/behavior/README.md, "Seats and the renderer").
  assert(span_rad > 0 && span_rad < 6.2831853f);
  std::vector<Seat> seats = arc_of(count, span_rad / static_cast<float>(std::max(count - 1, 1)), kSeatSpacingMm);
  std::vector<float> facings(seats.size());
  for (std::size_t i = 0; i < seats.size(); ++i) {
    // The partners' directions relative to the arc's centre all lie within
    // 90 degrees of it (inscribed angles), so their extremes bound them.
    float lo = 0, hi = 0;
    bool any = false;
    for (std::size_t j = 0; j < seats.size(); ++j) {
      if (j == i) continue;
      const float off = wrapped(yaw_toward(seats[i].origin_mm, seats[j].origin_mm) - seats[i].facing_yaw_rad);
      lo = any ? std::min(lo, off) : off;
      hi = any ? std::max(hi, off) : off;
      any = true;
    }
    // Facing the middle of its partners makes the farthest turn to any of
    // them the smallest (Kendon's F-formation: the body toward the shared
    // space, the head turning within it).
    const float toward_partners = any ? seats[i].facing_yaw_rad + 0.5f * (lo + hi) : 0.0f;
    facings[i] = std::clamp(wrapped(toward_partners), -kMaxFacingFromViewerRad, kMaxFacingFromViewerRad);
  }
  for (std::size_t i = 0; i < seats.size(); ++i) seats[i].facing_yaw_rad = facings[i];
  return seats;
}

std::vector<Seat> centre_facing_arc_layout(int count) {
  // Spread at most 270 degrees so that a large room stays an open ring.
  return arc_of(count, std::min(kSeatAngleRad, 4.712389f / static_cast<float>(std::max(count - 1, 1))),
                kCentreFacingArcSpacingMm);
}

SeatLayoutAngles seat_layout_angles(const std::vector<Seat>& seats) {
  SeatLayoutAngles a;
  double sum = 0;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < seats.size(); ++i) {
    a.largest_from_viewer_rad = std::max(a.largest_from_viewer_rad, std::fabs(wrapped(seats[i].facing_yaw_rad)));
    for (std::size_t j = 0; j < seats.size(); ++j) {
      if (j == i) continue;
      const float yaw =
          std::fabs(wrapped(yaw_toward(seats[i].origin_mm, seats[j].origin_mm) - seats[i].facing_yaw_rad));
      a.largest_partner_yaw_rad = std::max(a.largest_partner_yaw_rad, yaw);
      sum += yaw;
      ++pairs;
    }
  }
  if (pairs > 0) a.mean_partner_yaw_rad = static_cast<float>(sum / static_cast<double>(pairs));
  return a;
}

const HeadGeometry& head_geometry() {
  static const HeadGeometry geometry = [] {
    const model::GenericFace& face = model::generic_face();
    const float mm = model::kMillimetresPerUnit;
    HeadGeometry g{};
    // The point the renderer turns heads about (model/head_pose.hpp).
    g.neck_pivot_mm = model::kNeckPivot * mm;
    for (int side = 0; side < 2; ++side) g.eye_mm[side] = face.eyes[static_cast<std::size_t>(side)].centre * mm;
    g.eye_mid_mm = 0.5f * (g.eye_mm[0] + g.eye_mm[1]);
    g.interocular_mm = glm::length(g.eye_mm[0] - g.eye_mm[1]);
    glm::vec3 mouth(0.0f);
    for (std::uint32_t v : face.mouth_slit) mouth += face.skin.positions[v];
    if (!face.mouth_slit.empty()) mouth /= static_cast<float>(face.mouth_slit.size());
    g.mouth_mm = mouth * mm;
    return g;
  }();
  return geometry;
}

glm::vec3 head_to_seat(const HeadPose& pose, glm::vec3 p) {
  // The renderer's turn (model::head_rotation) about the pivot.
  const glm::vec3 pivot = head_geometry().neck_pivot_mm;
  return pose.translation_mm + pivot + model::head_rotation(pose) * (p - pivot);
}

glm::vec3 seat_to_room(const Seat& seat, glm::vec3 p) {
  const float c = std::cos(seat.facing_yaw_rad), s = std::sin(seat.facing_yaw_rad);
  return seat.origin_mm + glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
}

glm::vec3 room_to_seat(const Seat& seat, glm::vec3 p) {
  const glm::vec3 d = p - seat.origin_mm;
  const float c = std::cos(seat.facing_yaw_rad), s = std::sin(seat.facing_yaw_rad);
  return {c * d.x - s * d.z, d.y, s * d.x + c * d.z};
}

YawPitch direction_angles(glm::vec3 d) {
  const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
  return {std::atan2(d.x, d.z), std::atan2(d.y, horizontal)};
}

glm::vec3 direction_from_angles(YawPitch a) {
  return {std::sin(a.yaw_rad) * std::cos(a.pitch_rad), std::sin(a.pitch_rad), std::cos(a.yaw_rad) * std::cos(a.pitch_rad)};
}

}  // namespace fw::behavior
