#pragma once
// One frame of the first-person view worked out before anything is drawn:
// the others in their seat order on the view's arc, each face's parameters
// re-aimed at where its attention target sits in this view, and the
// viewer's own face for the self view. No renderer: testable on its own.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "first_person_layout.hpp"
#include "gaze_reaim.hpp"
#include "room_scene.hpp"

namespace fw::client {

struct PlacedFace {
  std::uint32_t id = 0;
  std::string name;
  glm::mat4 place{1.0f};
  codec::FaceParams params;  ///< re-aimed
};

struct ViewPlan {
  FirstPersonLayout layout;
  std::vector<PlacedFace> others;  ///< left to right
  /// The viewer's own face: as decoded but facing the camera (neutral before its first frame).
  codec::FaceParams self_params;
};

/// The plan of `scene` in a width x height frame. `blends` keeps each face's
/// correction across frames (smooth changes of target); faces no longer in
/// the scene are dropped from it.
ViewPlan plan_view(const RoomScene& scene, int width, int height, std::map<std::uint32_t, GazeBlend>& blends);

}  // namespace fw::client
