#pragma once
// Scenes: the FaceParams of every avatar of a room at every tick, what the
// codec benchmark measures on. The synthetic generator makes them; the
// behavior work will record real ones. File format (.fwscene, little-endian;
// codec/FORMAT.md, "Appendix: scene files"):
//
//   "FWSCENE1"                 8 bytes
//   u16 schema                 kFaceParamsSchema
//   u16 channels               fw::codec::kChannelCount floats per face
//   u16 fps                    1 .. 240
//   u16 avatars                1 .. kMaxSceneAvatars
//   u32 ticks                  1 .. kMaxSceneTicks
//   per avatar: u8 flags (bit 0: idle), u8 name length (0 .. 64), name (UTF-8)
//   per tick, per avatar: `channels` float32, in codec channel order
#include <cstdint>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::bench {

inline constexpr std::size_t kMaxSceneAvatars = 64;
inline constexpr std::size_t kMaxSceneTicks = 30 * 3600;  ///< an hour at 30 fps

struct SceneAvatar {
  std::string name;
  bool idle = false;  ///< nobody at the keyboard: the face rests, blinks, breathes
  std::vector<codec::FaceParams> ticks;  ///< one face per tick
};

struct Scene {
  std::string name;
  int fps = 30;
  std::vector<SceneAvatar> avatars;  ///< all with the same number of ticks

  std::size_t tick_count() const { return avatars.empty() ? 0 : avatars.front().ticks.size(); }
};

/// Writes `scene` to `path`; false (with `error` saying why) on failure.
bool write_scene(const Scene& scene, const std::string& path, std::string& error);
/// Reads a scene; its name is the file name without the extension. Every
/// count is checked against the limits and the file size before anything is
/// allocated.
bool read_scene(const std::string& path, Scene& scene, std::string& error);

}  // namespace fw::bench
