#pragma once
// Constants of the .fwa byte layout shared by the package reader and writer
// (avatar/photo/FORMAT.md is their description).
#include <array>
#include <cstddef>
#include <string_view>

namespace fw::model::package_layout {

inline constexpr std::array<std::uint8_t, 4> kMagic = {'F', 'W', 'A', 'V'};
inline constexpr std::size_t kHeaderBytes = 16;  // magic, version, flags, reserved, manifest length, manifest crc
inline constexpr std::string_view kFormatName = "facewire-avatar";
inline constexpr std::string_view kMeshType = "application/x-facewire-fit";
/// Fitted coordinates are stored as int16 in 1/4096 model units (0.015 mm on
/// an average face), range +-8 units.
inline constexpr float kCoordinateScale = 4096.0f;
/// Decoded images are bounded too: a package's textures are 256 or 512 px.
inline constexpr int kMaxImageSide = 1024;

}  // namespace fw::model::package_layout
