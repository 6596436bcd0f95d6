#pragma once
// A room's speaker that holds a neutral face, so that no smile of its own
// parts the lips, says a chat line: its faces in the second before the line
// and on every tick while the line is said. Shared by the tests of the
// spoken mouth and of what the tissue adds to it.
#include <string>
#include <vector>

#include "room_simulation.hpp"

namespace fw::test {

struct NeutralSpeaker {
  server::AvatarId id = 0;
  std::string refused;  ///< the neutral command's refusal, "" when taken
  std::vector<codec::FaceParams> before, during;
};

/// Adds the speaker "a" and a listener "b" to `room`, holds a's face
/// neutral for two seconds, then has it say `line` (for at most 8 s).
inline NeutralSpeaker neutral_speaker_says(server::RoomSimulation& room, const std::string& line) {
  NeutralSpeaker s;
  s.id = room.add_avatar({"a", true});
  room.add_avatar({"b", true});
  s.refused = room.command(s.id, server::ExpressCommand{"neutral", 1, 30});
  for (int i = 0; i < 60; ++i) room.tick();
  for (int i = 0; i < 30; ++i) {
    room.tick();
    s.before.push_back(room.face(s.id));
  }
  room.chat(s.id, line);
  for (int i = 0; i < 30 * 8 && (s.during.empty() || room.speaking(s.id)); ++i) {
    room.tick();
    if (room.speaking(s.id)) s.during.push_back(room.face(s.id));
  }
  return s;
}

}  // namespace fw::test
