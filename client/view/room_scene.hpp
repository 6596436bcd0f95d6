#pragma once
// What one frame of the room view shows, copied out of the RoomState under
// its lock: who is there, where the server seats them, whom each attends,
// each face's newest decoded parameters, and the last chat line.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"

namespace fw::client {

/// One avatar in one frame.
struct AvatarFace {
  std::uint32_t avatar = 0;  ///< room-frame avatar id
  codec::FaceParams params;
};

struct SceneMember {
  std::uint32_t id = 0;
  std::string name;
  codec::SeatInfo seat;                       ///< the server's seat (PROTOCOL.md 5.13)
  std::optional<codec::FaceParams> face;      ///< none before its first frame
  codec::Attention::Entry attention;          ///< whom it attends (5.14); the room until told
  bool still = false;                         ///< muted by the viewer: its face at rest, re-aimed at nobody
};

struct RoomScene {
  std::uint32_t you = 0;  ///< the viewer's avatar; 0 before the welcome
  std::string your_name;  ///< for the self view, known before the welcome
  std::vector<SceneMember> members;  ///< everyone known, the viewer included
  std::string caption;    ///< "name: text" of the last chat line, or empty
  std::chrono::steady_clock::time_point now{};
};

}  // namespace fw::client
