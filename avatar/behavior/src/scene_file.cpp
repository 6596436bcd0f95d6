#include "fw/behavior/scene_file.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>

#include "fw/codec/codec.hpp"

namespace fw::behavior {
namespace {

constexpr char kMagicV1[8] = {'F', 'W', 'S', 'C', 'E', 'N', 'E', '1'};
constexpr char kMagicV2[8] = {'F', 'W', 'S', 'C', 'E', 'N', 'E', '2'};
constexpr std::size_t kHeaderV1 = 8 + 2 * 4 + 4;
constexpr std::size_t kHeaderV2 = kHeaderV1 + 4;  // + u32 events
constexpr std::size_t kSeatBytes = 4 * 4;
constexpr std::size_t kEventFixedBytes = 4 + 2 + 1;

void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xFF));
  out.push_back(static_cast<char>(v >> 8));
}
void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put_f32(std::string& out, float f) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, 4);
  put_u32(out, bits);
}
std::uint32_t get_le(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
  return v;
}
float get_f32(const unsigned char* p) {
  const std::uint32_t bits = get_le(p, 4);
  float f = 0;
  std::memcpy(&f, &bits, 4);
  return f;
}

// Whether the scene carries anything version 1 cannot hold.
bool needs_v2(const Scene& scene) {
  if (!scene.events.empty()) return true;
  for (const SceneAvatar& a : scene.avatars)
    if (a.seat || a.joined_tick != 0 || a.left_tick != kPresentToTheEnd) return true;
  return false;
}

std::string limits_text() {
  return std::string("(1-") + std::to_string(kMaxSceneAvatars) + " avatars, 1-" + std::to_string(kMaxSceneTicks) +
         " ticks, 1-240 fps, at most " + std::to_string(kMaxSceneEvents) + " events)";
}

}  // namespace

bool write_scene(const Scene& scene, const std::string& path, std::string& error) {
  if (scene.avatars.empty() || scene.avatars.size() > kMaxSceneAvatars || scene.tick_count() == 0 ||
      scene.tick_count() > kMaxSceneTicks || scene.fps < 1 || scene.fps > 240 || scene.events.size() > kMaxSceneEvents) {
    error = std::string("scene out of limits ") + limits_text();
    return false;
  }
  const bool v2 = needs_v2(scene);
  std::string out(v2 ? kMagicV2 : kMagicV1, 8);
  put_u16(out, codec::kFaceParamsSchema);
  put_u16(out, static_cast<std::uint16_t>(codec::kChannelCount));
  put_u16(out, static_cast<std::uint16_t>(scene.fps));
  put_u16(out, static_cast<std::uint16_t>(scene.avatars.size()));
  put_u32(out, static_cast<std::uint32_t>(scene.tick_count()));
  if (v2) put_u32(out, static_cast<std::uint32_t>(scene.events.size()));
  const std::vector<Seat> layout = seat_layout(static_cast<int>(scene.avatars.size()));
  for (std::size_t i = 0; i < scene.avatars.size(); ++i) {
    const SceneAvatar& a = scene.avatars[i];
    if (a.ticks.size() != scene.tick_count() || a.name.size() > kMaxSceneNameBytes) {
      error = "avatar '" + a.name + "': every avatar needs the same tick count and a name of at most 64 bytes";
      return false;
    }
    out.push_back(static_cast<char>(a.idle ? 1 : 0));
    out.push_back(static_cast<char>(a.name.size()));
    out += a.name;
    if (v2) {
      put_u32(out, a.joined_tick);
      put_u32(out, a.left_tick);
      const Seat seat = a.seat.value_or(layout[i]);
      put_f32(out, seat.origin_mm.x);
      put_f32(out, seat.origin_mm.y);
      put_f32(out, seat.origin_mm.z);
      put_f32(out, seat.facing_yaw_rad);
    }
  }
  for (std::size_t t = 0; t < scene.tick_count(); ++t)
    for (const SceneAvatar& a : scene.avatars)
      for (std::size_t c = 0; c < codec::kChannelCount; ++c) put_f32(out, codec::channel_value(a.ticks[t], c));
  if (v2) {
    std::uint32_t last_tick = 0;
    for (const SceneEvent& e : scene.events) {
      if (e.avatar >= scene.avatars.size() || e.what.size() > kMaxSceneEventBytes || e.tick >= scene.tick_count() ||
          e.tick < last_tick) {
        error = "event '" + e.what + "' at tick " + std::to_string(e.tick) +
                ": events need an avatar of the scene, a tick of the scene in order, and at most 255 bytes";
        return false;
      }
      last_tick = e.tick;
      put_u32(out, e.tick);
      put_u16(out, e.avatar);
      out.push_back(static_cast<char>(e.what.size()));
      out += e.what;
    }
  }
  std::ofstream file(path, std::ios::binary);
  file.write(out.data(), static_cast<std::streamsize>(out.size()));
  if (!file) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

bool read_scene(const std::string& path, Scene& scene, std::string& error) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = "cannot read " + path + ": " + ec.message();
    return false;
  }
  const std::uintmax_t max_size = kHeaderV2 + kMaxSceneAvatars * (2 + kMaxSceneNameBytes + 8 + kSeatBytes) +
                                  std::uintmax_t{kMaxSceneTicks} * kMaxSceneAvatars * codec::kChannelCount * 4 +
                                  kMaxSceneEvents * (kEventFixedBytes + kMaxSceneEventBytes);
  if (size < kHeaderV1 || size > max_size) {
    error = path + ": not a scene file (size " + std::to_string(size) + " bytes)";
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  std::string bytes(kHeaderV1, '\0');
  // The magic first: a wrong file is refused before it is read whole.
  if (!file.read(bytes.data(), static_cast<std::streamsize>(kHeaderV1))) {
    error = "cannot read " + path;
    return false;
  }
  const bool v1 = std::memcmp(bytes.data(), kMagicV1, 8) == 0;
  const bool v2 = std::memcmp(bytes.data(), kMagicV2, 8) == 0;
  if (!v1 && !v2) {
    error = path + ": not a scene file (no FWSCENE1 or FWSCENE2 magic; a face script is text: run it with facewire-server script)";
    return false;
  }
  const std::size_t header = v2 ? kHeaderV2 : kHeaderV1;
  if (size < header) {
    error = path + ": scene header cut short";
    return false;
  }
  bytes.resize(size);
  if (!file.read(bytes.data() + kHeaderV1, static_cast<std::streamsize>(size - kHeaderV1))) {
    error = "cannot read " + path;
    return false;
  }
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint32_t schema = get_le(p + 8, 2), channels = get_le(p + 10, 2), fps = get_le(p + 12, 2),
                      avatars = get_le(p + 14, 2), ticks = get_le(p + 16, 4);
  const std::uint32_t events = v2 ? get_le(p + 20, 4) : 0;
  if (schema != codec::kFaceParamsSchema || channels != codec::kChannelCount) {
    error = path + ": scene of FaceParams schema " + std::to_string(schema) + " with " + std::to_string(channels) +
            " channels; this build reads schema " + std::to_string(codec::kFaceParamsSchema) + " with " +
            std::to_string(codec::kChannelCount);
    return false;
  }
  if (fps < 1 || fps > 240 || avatars < 1 || avatars > kMaxSceneAvatars || ticks < 1 || ticks > kMaxSceneTicks ||
      events > kMaxSceneEvents) {
    error = path + ": scene out of limits " + limits_text();
    return false;
  }
  std::size_t at = header;
  Scene parsed;
  parsed.name = std::filesystem::path(path).stem().string();
  parsed.fps = static_cast<int>(fps);
  const std::size_t avatar_extra = v2 ? 8 + kSeatBytes : 0;
  for (std::uint32_t a = 0; a < avatars; ++a) {
    if (at + 2 > size || p[at + 1] > kMaxSceneNameBytes || at + 2 + p[at + 1] + avatar_extra > size) {
      error = path + ": avatar list cut short";
      return false;
    }
    SceneAvatar avatar;
    avatar.idle = (p[at] & 1) != 0;
    avatar.name.assign(bytes, at + 2, p[at + 1]);
    at += 2 + p[at + 1];
    if (v2) {
      avatar.joined_tick = get_le(p + at, 4);
      avatar.left_tick = get_le(p + at + 4, 4);
      Seat seat;
      seat.origin_mm = {get_f32(p + at + 8), get_f32(p + at + 12), get_f32(p + at + 16)};
      seat.facing_yaw_rad = get_f32(p + at + 20);
      avatar.seat = seat;
      at += avatar_extra;
    }
    parsed.avatars.push_back(std::move(avatar));
  }
  const std::size_t face_bytes = codec::kChannelCount * 4;
  const std::size_t faces_size = std::size_t{ticks} * avatars * face_bytes;
  const bool faces_fit = v2 ? size - at >= faces_size + std::size_t{events} * kEventFixedBytes : size - at == faces_size;
  if (!faces_fit) {
    error = path + ": size does not match " + std::to_string(ticks) + " ticks of " + std::to_string(avatars) + " avatars";
    return false;
  }
  std::vector<float> face(codec::kChannelCount);
  for (SceneAvatar& a : parsed.avatars) a.ticks.reserve(ticks);
  for (std::uint32_t t = 0; t < ticks; ++t) {
    for (SceneAvatar& a : parsed.avatars) {
      codec::FaceParams params;
      for (std::size_t c = 0; c < codec::kChannelCount; ++c, at += 4) codec::set_channel_value(params, c, get_f32(p + at));
      a.ticks.push_back(params);
    }
  }
  parsed.events.reserve(events);
  for (std::uint32_t e = 0; e < events; ++e) {
    if (at + kEventFixedBytes > size || at + kEventFixedBytes + p[at + 6] > size) {
      error = path + ": event list cut short";
      return false;
    }
    SceneEvent event;
    event.tick = get_le(p + at, 4);
    event.avatar = static_cast<std::uint16_t>(get_le(p + at + 4, 2));
    event.what.assign(bytes, at + kEventFixedBytes, p[at + 6]);
    at += kEventFixedBytes + p[at + 6];
    if (event.avatar >= avatars || event.tick >= ticks) {
      error = path + ": event " + std::to_string(e) + " names an avatar or tick the scene does not have";
      return false;
    }
    parsed.events.push_back(std::move(event));
  }
  if (at != size) {
    error = path + ": size does not match " + std::to_string(ticks) + " ticks of " + std::to_string(avatars) +
            " avatars and " + std::to_string(events) + " events";
    return false;
  }
  scene = std::move(parsed);
  return true;
}

}  // namespace fw::behavior
