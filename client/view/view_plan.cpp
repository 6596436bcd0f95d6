#include "view_plan.hpp"

#include <glm/geometric.hpp>

#include "head_points.hpp"

namespace fw::client {
namespace {

glm::mat4 server_place_of(const SceneMember& m) {
  return seat_place(m.seat.x_mm, m.seat.y_mm, m.seat.z_mm, m.seat.facing_yaw_rad);
}

const SceneMember* find_member(const RoomScene& scene, std::uint32_t id) {
  for (const SceneMember& m : scene.members)
    if (m.id == id) return &m;
  return nullptr;
}

// Where a member's eyes are at the server (its decoded head pose, neutral
// before its first frame).
glm::vec3 server_eyes(const SceneMember& m) { return eyes_at(server_place_of(m), m.face.value_or(codec::FaceParams{})); }

// Two seats closer than this (model units, about 6 cm) are no seats at all:
// a server that sent none leaves every seat at the origin, and no direction
// between them means anything.
constexpr float kDistinctSeats = 1.0f;

struct Aimed {
  codec::Attention::Entry key;  ///< what the blend follows (the room when the target cannot be aimed at)
  GazeCorrection correction;
};

Aimed aim_face(const RoomScene& scene, const SceneMember& face, const glm::mat4& view_place,
               const std::map<std::uint32_t, glm::mat4>& view_places, const FirstPersonLayout& layout) {
  const codec::FaceParams& p = *face.face;
  const glm::mat4 server_place = server_place_of(face);
  const glm::vec3 own_eyes = eyes_at(server_place, p);
  const codec::Attention::Entry& a = face.attention;
  const SceneMember* viewer = find_member(scene, scene.you);
  if (a.target == codec::AttentionTarget::avatar) {
    const SceneMember* target = find_member(scene, a.target_avatar);
    const auto in_view = view_places.find(a.target_avatar);
    if (target && target->id != face.id && glm::length(server_eyes(*target) - own_eyes) > kDistinctSeats) {
      if (target->id == scene.you)
        return {a, correction_toward(p, server_place, server_eyes(*target), view_place, viewer_eyes(layout), true)};
      if (in_view != view_places.end())
        return {a, correction_toward(p, server_place, server_eyes(*target), view_place,
                                     eyes_at(in_view->second, target->face.value_or(codec::FaceParams{})), false)};
    }
  }
  // The room, nobody, or a target this view cannot place: turned by the
  // change of facing toward the viewer only.
  codec::Attention::Entry room_key{face.id, a.target == codec::AttentionTarget::nobody ? a.target : codec::AttentionTarget::room, 0};
  if (!viewer || glm::length(server_eyes(*viewer) - own_eyes) <= kDistinctSeats) return {room_key, {}};
  return {room_key, correction_of_facing(p, server_place, server_eyes(*viewer), view_place, viewer_eyes(layout))};
}

// The viewer's own face as a camera in front of them would see it: its
// expression, lids and colour as decoded, head and eyes turned to the
// camera (the server turns them toward whom the viewer attends).
codec::FaceParams facing_the_camera(codec::FaceParams p) {
  p.head_yaw_rad = p.head_pitch_rad = 0.0f;
  p.eye_left = p.eye_right = {};
  return p;
}

}  // namespace

ViewPlan plan_view(const RoomScene& scene, int width, int height, std::map<std::uint32_t, GazeBlend>& blends) {
  ViewPlan plan;
  std::vector<SeatedAvatar> seated;
  for (const SceneMember& m : scene.members) {
    if (m.id == scene.you) {
      if (m.face) plan.self_params = facing_the_camera(*m.face);
    } else if (m.face) {
      seated.push_back({m.id, m.seat});
    }
  }
  const std::vector<std::uint32_t> order = others_left_to_right(seated, scene.you);
  plan.layout = first_person_layout(static_cast<int>(order.size()), width, height);
  std::map<std::uint32_t, glm::mat4> view_places;
  for (std::size_t i = 0; i < order.size(); ++i) view_places[order[i]] = plan.layout.places[i];

  std::map<std::uint32_t, GazeBlend> kept;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const SceneMember& m = *find_member(scene, order[i]);
    if (m.still) {  // muted: straight ahead from its place in this view, toward nobody
      plan.others.push_back({m.id, m.name, view_places[m.id], *m.face});
      continue;
    }
    const Aimed aimed = aim_face(scene, m, view_places[m.id], view_places, plan.layout);
    GazeBlend& blend = kept[m.id] = blends[m.id];
    const GazeCorrection correction = blend.update(aimed.key, aimed.correction, scene.now);
    plan.others.push_back({m.id, m.name, view_places[m.id], apply_correction(*m.face, correction)});
  }
  blends = std::move(kept);
  return plan;
}

}  // namespace fw::client
