#pragma once
// Scenes: the FaceParams of every avatar of a room at every tick, unquantised,
// plus what happened (behavior changes, blushes, chat, commands). The room
// simulation (`facewire-server simulate`) records them, the codec benchmark
// measures on them, `facewire-server render-scene` turns them into video.
// Format: codec/FORMAT.md, "Appendix A. Scene files". Version 2 adds seats,
// presence and events, version 3 the faces' corrective weights; version 1
// files (faces only) and version 2 files are still read (their correctives
// are 0), and a scene is written in the oldest version that holds it. A version
// 1 file was recorded before seats were stored, when every room sat on
// centre_facing_arc_layout: an avatar without a seat sits there (scene_seat),
// so an old recording keeps the seats its gazes were aimed from.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fw/behavior/seat_layout.hpp"
#include "fw/codec/face_params.hpp"

namespace fw::behavior {

// What a scene file may hold; a reader refuses more before it allocates.
inline constexpr int kMaxSceneFps = 240;
inline constexpr std::size_t kMaxSceneAvatars = 64;
inline constexpr std::size_t kMaxSceneTicks = 30 * 3600;  ///< an hour at 30 fps
inline constexpr std::size_t kMaxSceneEvents = 1'000'000;
inline constexpr std::size_t kMaxSceneEventBytes = 255;
inline constexpr std::size_t kMaxSceneNameBytes = 64;
inline constexpr std::uint32_t kPresentToTheEnd = 0xFFFFFFFFu;

struct SceneAvatar {
  std::string name;
  bool idle = false;  ///< nobody at the keyboard: the face rests, blinks, breathes (the codec budgets it less)
  std::vector<codec::FaceParams> ticks;  ///< one face per tick (neutral while absent)
  /// In the room from this tick until (excluding) that one.
  std::uint32_t joined_tick = 0;
  std::uint32_t left_tick = kPresentToTheEnd;
  std::optional<Seat> seat{};  ///< where the room seated it (version 2); none: scene_seat

  bool present(std::size_t tick) const { return tick >= joined_tick && tick < left_tick; }
};

struct SceneEvent {
  std::uint32_t tick = 0;
  std::uint16_t avatar = 0;  ///< index into Scene::avatars
  std::string what;          ///< at most kMaxSceneEventBytes
};

struct Scene {
  std::string name;
  int fps = 30;
  std::vector<SceneAvatar> avatars;  ///< all with the same number of ticks
  std::vector<SceneEvent> events;    ///< in tick order

  std::size_t tick_count() const { return avatars.empty() ? 0 : avatars.front().ticks.size(); }
};

/// Where avatar `index` of `scene` sits: its own seat, or, without one, its
/// seat on centre_facing_arc_layout for the scene's avatars (where version 1
/// recordings were made; never seat_layout, whose seats turn toward each
/// other and would change what an old file shows).
Seat scene_seat(const Scene& scene, std::size_t index);

/// Writes `scene` to `path`; false (with `error` saying why) on failure.
bool write_scene(const Scene& scene, const std::string& path, std::string& error);
/// Reads a scene of version 1, 2 or 3; its name is the file name without the
/// extension. Every count is checked against the limits and the file size
/// before anything is allocated; `error` names the file and says what was
/// wrong at which byte.
bool read_scene(const std::string& path, Scene& scene, std::string& error);

/// The bytes of the scene file for `scene` (version 3 when a face carries a
/// corrective weight, else version 1 when it carries nothing of version 2),
/// appended to `out`; false (with `error`) when the
/// scene is outside the limits or does not add up.
bool write_scene_bytes(const Scene& scene, std::vector<std::uint8_t>& out, std::string& error);
/// Parses the whole of a scene file (`scene.name` is left empty). On
/// failure `scene` is untouched and `error` says what was wrong and at
/// which byte. Any bytes at all are safe to pass (tests/fuzz/scene_file_fuzz).
bool read_scene_bytes(std::span<const std::uint8_t> bytes, Scene& scene, std::string& error);

}  // namespace fw::behavior
