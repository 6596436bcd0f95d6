#include "mute_list_golden.hpp"

#include <cstdint>
#include <string>
#include <vector>

#include "mute_list.hpp"

namespace fw::test::web_golden {
namespace {

nlohmann::json face_json(const codec::FaceParams& p) {
  return {{"au", p.au},
          {"head_yaw_rad", p.head_yaw_rad},
          {"head_pitch_rad", p.head_pitch_rad},
          {"head_roll_rad", p.head_roll_rad},
          {"head_translation_mm", p.head_translation_mm},
          {"eye_left", {{"yaw_rad", p.eye_left.yaw_rad}, {"pitch_rad", p.eye_left.pitch_rad}}},
          {"eye_right", {{"yaw_rad", p.eye_right.yaw_rad}, {"pitch_rad", p.eye_right.pitch_rad}}},
          {"lid_left", p.lid_left},
          {"lid_right", p.lid_right},
          {"blush", p.blush},
          {"pallor", p.pallor}};
}

}  // namespace

nlohmann::json mute_list_golden() {
  // Names as people type them: case, blanks and non-ASCII letters matter
  // (a display name is compared byte for byte, as the protocol carries it).
  const std::vector<std::string> muted = {"Bob", "ann marie", "Zoë", "李"};
  const client::MuteList list(muted);
  const std::vector<std::string> names = {"Bob", "bob", "Bob ", "ann marie", "Ann Marie", "Zoë", "Zoe", "李", "", "Carol"};
  // The viewer is 7; 0 is the server itself (never a person).
  const std::vector<std::uint32_t> ids = {0, 1, 7, 8, 2097151};
  const std::uint32_t you = 7;
  nlohmann::json cases = nlohmann::json::array();
  for (std::uint32_t id : ids)
    for (const std::string& name : names)
      cases.push_back({{"id", id}, {"name", name}, {"mutes", list.mutes(id, name, you)}});
  nlohmann::json out;
  out["about"] =
      "client/room/mute_list.hpp (MuteList::mutes, still_face), written by tests/web/golden; "
      "web/room/mute_list.js (MuteList.mutes, NEUTRAL_FACE) must give the same";
  out["muted"] = muted;
  out["you"] = you;
  out["cases"] = cases;
  out["still_face"] = face_json(client::MuteList::still_face());
  return out;
}

}  // namespace fw::test::web_golden
