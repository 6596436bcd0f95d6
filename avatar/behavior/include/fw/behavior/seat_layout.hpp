#pragma once
// Where the avatars of a room sit and where the parts of their heads are, in
// one room frame, so that the angle from one face's eyes to another's is the
// one the renderer shows.
//
// Room frame: millimetres; x to the viewer's right, y up, z toward the
// viewer: the renderer's world frame times kMillimetresPerUnit. A seat holds
// a head in its model frame (the generic face's, in millimetres: x toward the
// person's left, y up, z out of the face) turned by `facing_yaw_rad` about y
// and moved to `origin_mm`. The renderer places a face there with
// translate(origin_mm / kMillimetresPerUnit) * rotate_y(facing_yaw_rad).
#include <vector>

#include <glm/vec3.hpp>

#include "fw/model/head_pose.hpp"

namespace fw::behavior {

struct Seat {
  glm::vec3 origin_mm{0.0f};  ///< where the head's model origin stands
  float facing_yaw_rad = 0;   ///< same sign as head yaw: positive turns toward the person's left
};

/// The seats of a room of `count` avatars: an arc open toward the viewer
/// (the room's +z), neighbours kSeatSpacingMm apart, spread evenly over
/// kSeatArcSpanRad, each seat
/// turned from the viewer toward its partners: to the middle of the
/// directions in which it sees them, but never more than
/// kMaxFacingFromViewerRad from the viewer, so that the viewer sees every
/// face at rest at most three-quarter. A single seat faces the viewer.
/// Facings fall from the viewer's left to the viewer's right seat (a seat
/// further right is turned more toward the viewer's left), never rising.
inline constexpr float kSeatSpacingMm = 600.0f;
inline constexpr float kSeatAngleRad = 0.8726646f;    ///< 50 degrees
inline constexpr float kSeatArcSpanRad = 2.0943951f;  ///< 120 degrees, see seat_layout.cpp
/// 60 degrees. Expressions are categorised about as well from the
/// mid-profile (45 degrees) as from the front, but a profile (90 degrees)
/// weakens every one and loses some disgust and sadness (Guo & Shaw 2015,
/// Acta Psychologica 155: 19-28): a face at rest stays nearer three-quarter.
inline constexpr float kMaxFacingFromViewerRad = 1.0471976f;
/// `span_rad` (above 0, below 2 pi): another spread, to measure the choice.
std::vector<Seat> seat_layout(int count, float span_rad = kSeatArcSpanRad);

/// Neighbours' distance on that older arc: version 1 scenes were recorded so.
inline constexpr float kCentreFacingArcSpacingMm = 420.0f;
/// The layout before seats were turned toward their partners: an arc open
/// toward the viewer, neighbours kCentreFacingArcSpacingMm and at most
/// kSeatAngleRad apart on it, over at most 270 degrees, every seat facing
/// the arc's centre. A scene file of version 1 stores no seats; it was
/// recorded on these (scene_file.hpp).
std::vector<Seat> centre_facing_arc_layout(int count);

/// What a layout asks of heads and shows a viewer far away on +z: the
/// largest angle between a seat's facing and the direction to another seat
/// (the head yaw a face needs to look at that partner), its mean over all
/// pairs, and the largest angle between a facing and the viewer.
struct SeatLayoutAngles {
  float largest_partner_yaw_rad = 0, mean_partner_yaw_rad = 0, largest_from_viewer_rad = 0;
};
SeatLayoutAngles seat_layout_angles(const std::vector<Seat>& seats);

/// Head pose (the head's rotation about the neck pivot, FaceParams' signs).
using model::HeadPose;

/// Points of the generic head in its model frame (millimetres): the neck
/// pivot the head turns about, each eye's rotation centre, the mouth.
struct HeadGeometry {
  glm::vec3 neck_pivot_mm;
  glm::vec3 eye_mm[2];  ///< indexed like model::Side: person's right, left
  glm::vec3 eye_mid_mm;
  glm::vec3 mouth_mm;
  float interocular_mm;
};
const HeadGeometry& head_geometry();

/// A point of the head's model frame, with the head at `pose`, in the seat's
/// frame (the head's model frame at rest).
glm::vec3 head_to_seat(const HeadPose& pose, glm::vec3 p_head_mm);
/// A point of the seat frame in the room frame and back.
glm::vec3 seat_to_room(const Seat& seat, glm::vec3 p_seat_mm);
glm::vec3 room_to_seat(const Seat& seat, glm::vec3 p_room_mm);

/// Yaw and pitch (FaceParams' signs) of direction `d` in a seat frame; 0,0 is
/// straight ahead out of the face.
struct YawPitch {
  float yaw_rad = 0, pitch_rad = 0;
};
YawPitch direction_angles(glm::vec3 d);
glm::vec3 direction_from_angles(YawPitch a);

}  // namespace fw::behavior
