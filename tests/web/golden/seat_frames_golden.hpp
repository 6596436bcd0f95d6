#pragma once
// Golden file of the room's frames as avatar/behavior's seat_layout makes
// them (seats on the arc, seat to room and back, the yaw and pitch of a
// direction, the aim from a face's eyes at a point), which the browser's
// web/room/view_geometry.js and gaze_reaim.js (aimAt) port: the browser
// moves a face's aim from the server's seats to its own view with them.
#include <nlohmann/json.hpp>

namespace fw::test::web_golden {

nlohmann::json seat_frames_golden();

}  // namespace fw::test::web_golden
