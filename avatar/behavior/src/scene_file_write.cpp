// Scene file writing: the scene is checked whole first (what the reader
// would refuse is never written), then written part by part.
#include <cmath>

#include "fw/codec/byte_writer.hpp"
#include "fw/codec/codec.hpp"
#include "scene_file_layout.hpp"

namespace fw::behavior {
namespace {

namespace layout = scene_layout;

// Whether the scene carries anything version 1 cannot hold.
bool needs_v2(const Scene& scene) {
  if (!scene.events.empty()) return true;
  for (const SceneAvatar& a : scene.avatars)
    if (a.seat || a.joined_tick != 0 || a.left_tick != kPresentToTheEnd) return true;
  return false;
}

// Whether any face carries a corrective weight (version 3 stores them).
bool needs_v3(const Scene& scene) {
  for (const SceneAvatar& a : scene.avatars)
    for (const codec::FaceParams& face : a.ticks)
      for (const float w : face.corrective)
        if (w != 0.0f) return true;
  return false;
}

bool fail(std::string& error, std::string what) {
  error = std::move(what);
  return false;
}

bool faces_finite(const SceneAvatar& avatar) {
  for (const codec::FaceParams& face : avatar.ticks)
    for (std::size_t c = 0; c < codec::kChannelCount; ++c)
      if (!std::isfinite(codec::channel_value(face, c))) return false;
  return true;
}

bool seat_finite(const SceneAvatar& avatar) {
  if (!avatar.seat) return true;
  const Seat& s = *avatar.seat;
  return std::isfinite(s.origin_mm.x) && std::isfinite(s.origin_mm.y) && std::isfinite(s.origin_mm.z) &&
         std::isfinite(s.facing_yaw_rad);
}

bool check_avatar(const SceneAvatar& a, std::size_t ticks, std::string& error) {
  if (a.ticks.size() != ticks || a.name.size() > kMaxSceneNameBytes)
    return fail(error, "avatar '" + a.name + "': every avatar needs the same tick count and a name of at most 64 bytes");
  if (!layout::presence_fits(a, ticks))
    return fail(error, "avatar '" + a.name + "' joins at tick " + std::to_string(a.joined_tick) + " and leaves at tick " +
                           std::to_string(a.left_tick) + ": it must join at a tick of the scene and leave after that");
  if (!faces_finite(a) || !seat_finite(a))
    return fail(error, "avatar '" + a.name + "': a face value or its seat is not a finite number");
  return true;
}

bool check_events(const Scene& scene, std::string& error) {
  std::uint32_t last_tick = 0;
  for (const SceneEvent& e : scene.events) {
    if (e.avatar >= scene.avatars.size() || e.what.size() > kMaxSceneEventBytes || e.tick >= scene.tick_count() ||
        e.tick < last_tick)
      return fail(error, "event '" + e.what + "' at tick " + std::to_string(e.tick) +
                             ": events need an avatar of the scene, a tick of the scene in order, and at most 255 bytes");
    last_tick = e.tick;
  }
  return true;
}

// What the reader would refuse, refused before a byte is written.
bool check_scene(const Scene& scene, std::string& error) {
  if (scene.avatars.empty() || scene.avatars.size() > kMaxSceneAvatars || scene.tick_count() == 0 ||
      scene.tick_count() > kMaxSceneTicks || scene.fps < 1 || scene.fps > kMaxSceneFps ||
      scene.events.size() > kMaxSceneEvents)
    return fail(error, "scene out of limits " + layout::limits_text());
  for (const SceneAvatar& a : scene.avatars)
    if (!check_avatar(a, scene.tick_count(), error)) return false;
  return check_events(scene, error);
}

void write_header(codec::ByteWriter& w, const Scene& scene, int version) {
  w.bytes(layout::kMagicStem);
  w.u8(static_cast<std::uint8_t>('0' + version));
  w.u16_le(layout::schema_of(version));
  w.u16_le(static_cast<std::uint16_t>(layout::channels_of(version)));
  w.u16_le(static_cast<std::uint16_t>(scene.fps));
  w.u16_le(static_cast<std::uint16_t>(scene.avatars.size()));
  w.u32_le(static_cast<std::uint32_t>(scene.tick_count()));
  if (version >= 2) w.u32_le(static_cast<std::uint32_t>(scene.events.size()));
}

void write_avatars(codec::ByteWriter& w, const Scene& scene, int version) {
  // Versions 2 and 3 give every avatar a seat: where version 1 seated it, when the scene gives none.
  for (std::size_t i = 0; i < scene.avatars.size(); ++i) {
    const SceneAvatar& a = scene.avatars[i];
    w.u8(a.idle ? layout::kFlagIdle : 0);
    w.u8(static_cast<std::uint8_t>(a.name.size()));
    w.bytes({reinterpret_cast<const std::uint8_t*>(a.name.data()), a.name.size()});
    if (version < 2) continue;
    w.u32_le(a.joined_tick);
    w.u32_le(a.left_tick);
    const Seat seat = scene_seat(scene, i);
    w.f32_le(seat.origin_mm.x);
    w.f32_le(seat.origin_mm.y);
    w.f32_le(seat.origin_mm.z);
    w.f32_le(seat.facing_yaw_rad);
  }
}

void write_faces(codec::ByteWriter& w, const Scene& scene, int version) {
  const std::size_t channels = layout::channels_of(version);
  for (std::size_t t = 0; t < scene.tick_count(); ++t)
    for (const SceneAvatar& a : scene.avatars)
      for (std::size_t c = 0; c < channels; ++c) w.f32_le(codec::channel_value(a.ticks[t], c));
}

void write_events(codec::ByteWriter& w, const Scene& scene) {
  for (const SceneEvent& e : scene.events) {
    w.u32_le(e.tick);
    w.u16_le(e.avatar);
    w.u8(static_cast<std::uint8_t>(e.what.size()));
    w.bytes({reinterpret_cast<const std::uint8_t*>(e.what.data()), e.what.size()});
  }
}

}  // namespace

bool write_scene_bytes(const Scene& scene, std::vector<std::uint8_t>& out, std::string& error) {
  if (!check_scene(scene, error)) return false;
  const int version = needs_v3(scene) ? 3 : needs_v2(scene) ? 2 : 1;
  out.reserve(out.size() + layout::kHeaderBytesV2 +
              scene.tick_count() * scene.avatars.size() * layout::face_bytes(version));
  codec::ByteWriter w(out);
  write_header(w, scene, version);
  write_avatars(w, scene, version);
  write_faces(w, scene, version);
  if (version >= 2) write_events(w, scene);
  return true;
}

}  // namespace fw::behavior
