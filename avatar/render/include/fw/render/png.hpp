#pragma once
#include <filesystem>
#include <string>

#include "fw/model/image.hpp"

namespace fw::render {

/// Writes `image` as an 8-bit RGBA PNG.
/// @return false and `error` (naming the path and the reason) on failure
bool write_png(const model::RgbaImage& image, const std::filesystem::path& path, std::string& error);

}  // namespace fw::render
