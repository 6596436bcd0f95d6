// Scene files on disk: the whole file in memory, checked against the limits
// before it is read (scene_file_read.cpp parses it, scene_file_write.cpp
// makes it).
#include "fw/behavior/scene_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "scene_file_layout.hpp"

namespace fw::behavior {
namespace {

namespace layout = scene_layout;

// Reads the file's first `count` bytes (all of them when it is shorter).
bool read_file_bytes(std::ifstream& file, std::size_t count, std::vector<std::uint8_t>& bytes) {
  const std::size_t before = bytes.size();
  bytes.resize(before + count);
  return static_cast<bool>(
      file.read(reinterpret_cast<char*>(bytes.data() + before), static_cast<std::streamsize>(count)));
}

// The whole file, once its size and its magic say it may be a scene: a large
// file of another kind is refused before it is read.
bool read_scene_file(const std::string& path, std::vector<std::uint8_t>& bytes, std::string& error) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = "cannot read " + path + ": " + ec.message();
    return false;
  }
  if (size > layout::kMaxFileBytes) {
    error = path + ": not a scene file: " + std::to_string(size) + " bytes, more than the largest scene (" +
            std::to_string(layout::kMaxFileBytes) + " bytes) " + layout::limits_text();
    return false;
  }
  std::ifstream file(path, std::ios::binary);
  const std::size_t magic_bytes = std::min<std::size_t>(size, layout::kMagicBytes);
  if (!read_file_bytes(file, magic_bytes, bytes)) {
    error = "cannot read " + path;
    return false;
  }
  codec::ByteReader magic(bytes);
  if (layout::read_magic(magic, error) == 0) {
    error = path + ": " + error;
    return false;
  }
  if (!read_file_bytes(file, static_cast<std::size_t>(size) - magic_bytes, bytes)) {
    error = "cannot read " + path;
    return false;
  }
  return true;
}

}  // namespace

Seat scene_seat(const Scene& scene, std::size_t index) {
  if (scene.avatars[index].seat) return *scene.avatars[index].seat;
  return centre_facing_arc_layout(static_cast<int>(scene.avatars.size()))[index];
}

bool read_scene(const std::string& path, Scene& scene, std::string& error) {
  std::vector<std::uint8_t> bytes;
  if (!read_scene_file(path, bytes, error)) return false;
  Scene parsed;
  if (!read_scene_bytes(bytes, parsed, error)) {
    error = path + ": " + error;
    return false;
  }
  parsed.name = std::filesystem::path(path).stem().string();
  scene = std::move(parsed);
  return true;
}

bool write_scene(const Scene& scene, const std::string& path, std::string& error) {
  std::vector<std::uint8_t> bytes;
  if (!write_scene_bytes(scene, bytes, error)) return false;
  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!file) {
    error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace fw::behavior
