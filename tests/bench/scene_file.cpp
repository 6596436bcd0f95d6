#include "scene_file.hpp"

#include <cstring>
#include <filesystem>
#include <fstream>

#include "fw/codec/codec.hpp"

namespace fw::bench {
namespace {

constexpr char kMagic[8] = {'F', 'W', 'S', 'C', 'E', 'N', 'E', '1'};
constexpr std::size_t kMaxNameBytes = 64;

// The codec's channel order: FaceParams fields as the codec quantises them.
std::vector<float> flatten(const codec::FaceParams& p) {
  std::vector<float> v(codec::kChannelCount);
  for (std::size_t c = 0; c < v.size(); ++c) v[c] = codec::channel_value(p, c);
  return v;
}

codec::FaceParams unflatten(const float* v) {
  codec::FaceParams p;
  for (std::size_t c = 0; c < codec::kChannelCount; ++c) codec::set_channel_value(p, c, v[c]);
  return p;
}

void put_u16(std::string& out, std::uint16_t v) {
  out.push_back(static_cast<char>(v & 0xFF));
  out.push_back(static_cast<char>(v >> 8));
}
void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
std::uint32_t get_le(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
  return v;
}

}  // namespace

bool write_scene(const Scene& scene, const std::string& path, std::string& error) {
  if (scene.avatars.empty() || scene.avatars.size() > kMaxSceneAvatars || scene.tick_count() == 0 ||
      scene.tick_count() > kMaxSceneTicks || scene.fps < 1 || scene.fps > 240) {
    error = "scene out of limits (1-64 avatars, 1-108000 ticks, 1-240 fps)";
    return false;
  }
  std::string out(kMagic, sizeof kMagic);
  put_u16(out, codec::kFaceParamsSchema);
  put_u16(out, static_cast<std::uint16_t>(codec::kChannelCount));
  put_u16(out, static_cast<std::uint16_t>(scene.fps));
  put_u16(out, static_cast<std::uint16_t>(scene.avatars.size()));
  put_u32(out, static_cast<std::uint32_t>(scene.tick_count()));
  for (const SceneAvatar& a : scene.avatars) {
    if (a.ticks.size() != scene.tick_count() || a.name.size() > kMaxNameBytes) {
      error = "avatar '" + a.name + "': every avatar needs the same tick count and a name of at most 64 bytes";
      return false;
    }
    out.push_back(static_cast<char>(a.idle ? 1 : 0));
    out.push_back(static_cast<char>(a.name.size()));
    out += a.name;
  }
  for (std::size_t t = 0; t < scene.tick_count(); ++t) {
    for (const SceneAvatar& a : scene.avatars) {
      for (float f : flatten(a.ticks[t])) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &f, 4);
        put_u32(out, bits);
      }
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
  constexpr std::uintmax_t kHeader = 8 + 2 * 4 + 4;
  const std::uintmax_t max_size =
      kHeader + kMaxSceneAvatars * (2 + kMaxNameBytes) + kMaxSceneTicks * kMaxSceneAvatars * codec::kChannelCount * 4;
  if (ec) {
    error = "cannot read " + path + ": " + ec.message();
    return false;
  }
  if (size < kHeader || size > max_size) {
    error = path + ": not a scene file (size " + std::to_string(size) + " bytes)";
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  std::string bytes(kHeader, '\0');
  // The magic first: a wrong file is refused before it is read whole.
  if (!file.read(bytes.data(), static_cast<std::streamsize>(kHeader)) || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) {
    error = path + ": not a scene file (no FWSCENE1 magic)";
    return false;
  }
  bytes.resize(size);
  if (!file.read(bytes.data() + kHeader, static_cast<std::streamsize>(size - kHeader))) {
    error = "cannot read " + path;
    return false;
  }
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint32_t schema = get_le(p + 8, 2), channels = get_le(p + 10, 2), fps = get_le(p + 12, 2),
                      avatars = get_le(p + 14, 2), ticks = get_le(p + 16, 4);
  if (schema != codec::kFaceParamsSchema || channels != codec::kChannelCount) {
    error = path + ": scene of FaceParams schema " + std::to_string(schema) + " with " + std::to_string(channels) +
            " channels; this build reads schema 1 with 47";
    return false;
  }
  if (fps < 1 || fps > 240 || avatars < 1 || avatars > kMaxSceneAvatars || ticks < 1 || ticks > kMaxSceneTicks) {
    error = path + ": scene out of limits (1-240 fps, 1-64 avatars, 1-108000 ticks)";
    return false;
  }
  std::size_t at = kHeader;
  Scene parsed;
  parsed.name = std::filesystem::path(path).stem().string();
  parsed.fps = static_cast<int>(fps);
  for (std::uint32_t a = 0; a < avatars; ++a) {
    if (at + 2 > size || at + 2 + p[at + 1] > size || p[at + 1] > kMaxNameBytes) {
      error = path + ": avatar list cut short";
      return false;
    }
    SceneAvatar avatar;
    avatar.idle = (p[at] & 1) != 0;
    avatar.name.assign(bytes, at + 2, p[at + 1]);
    at += 2 + p[at + 1];
    parsed.avatars.push_back(std::move(avatar));
  }
  const std::size_t face_bytes = codec::kChannelCount * 4;
  if (size - at != std::size_t{ticks} * avatars * face_bytes) {
    error = path + ": size does not match " + std::to_string(ticks) + " ticks of " + std::to_string(avatars) + " avatars";
    return false;
  }
  std::vector<float> face(codec::kChannelCount);
  for (SceneAvatar& a : parsed.avatars) a.ticks.reserve(ticks);
  for (std::uint32_t t = 0; t < ticks; ++t) {
    for (SceneAvatar& a : parsed.avatars) {
      for (std::size_t c = 0; c < codec::kChannelCount; ++c, at += 4) {
        const std::uint32_t bits = get_le(p + at, 4);
        std::memcpy(&face[c], &bits, 4);
      }
      a.ticks.push_back(unflatten(face.data()));
    }
  }
  scene = std::move(parsed);
  return true;
}

}  // namespace fw::bench
