// Fuzzes read_scene_bytes (scene files are user input: recordings people
// pass to render-scene and the codec benchmark): any input gives an error
// that says something, or a scene within the limits whose parts add up, and
// that the writer turns back into exactly the bytes read (the format has one
// way to write each scene, so a reader that accepted anything else would be
// reading something the writer cannot have made).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "fw/behavior/scene_file.hpp"
#include "fw/codec/codec.hpp"
#include "seed_check.hpp"

namespace {

using namespace fw::behavior;

bool avatar_adds_up(const SceneAvatar& a, std::size_t ticks, bool version2) {
  if (a.name.size() > kMaxSceneNameBytes || a.ticks.size() != ticks || a.seat.has_value() != version2) return false;
  if (a.joined_tick >= ticks || (a.left_tick != kPresentToTheEnd && (a.left_tick <= a.joined_tick || a.left_tick > ticks)))
    return false;
  for (const fw::codec::FaceParams& face : a.ticks)
    for (std::size_t c = 0; c < fw::codec::kChannelCount; ++c)
      if (!std::isfinite(fw::codec::channel_value(face, c))) return false;
  return true;
}

bool scene_adds_up(const Scene& scene, bool version2) {
  const std::size_t ticks = scene.tick_count();
  if (scene.avatars.empty() || scene.avatars.size() > kMaxSceneAvatars || ticks == 0 || ticks > kMaxSceneTicks ||
      scene.fps < 1 || scene.fps > kMaxSceneFps || scene.events.size() > kMaxSceneEvents || !scene.name.empty())
    return false;
  for (const SceneAvatar& a : scene.avatars)
    if (!avatar_adds_up(a, ticks, version2)) return false;
  std::uint32_t previous_tick = 0;
  for (const SceneEvent& e : scene.events) {
    if (e.avatar >= scene.avatars.size() || e.tick >= ticks || e.tick < previous_tick || e.what.size() > 255)
      return false;
    previous_tick = e.tick;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  Scene scene;
  std::string error;
  const bool ok = read_scene_bytes(bytes, scene, error);
  if (ok == !error.empty()) std::abort();  // exactly one of: a scene, or a reason
  if (!ok) {
    fw::fuzz::seed_refused(error);
    return 0;
  }
  if (!scene_adds_up(scene, size >= 8 && data[7] >= '2')) std::abort();  // versions 2 and 3 seat every avatar
  std::vector<std::uint8_t> written;
  if (!write_scene_bytes(scene, written, error)) std::abort();
  if (written.size() != size || !std::equal(written.begin(), written.end(), bytes.begin())) std::abort();
  return 0;
}
