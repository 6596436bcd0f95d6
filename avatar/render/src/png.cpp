#include "fw/render/png.hpp"

#include <png.h>

namespace fw::render {

bool write_png(const model::RgbaImage& image, const std::filesystem::path& path, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGBA;
  if (!png_image_write_to_file(&png, path.c_str(), 0, image.pixels.data(), 0, nullptr)) {
    error = "cannot write " + path.string() + ": " + png.message +
            " (check that the directory exists and is writable)";
    return false;
  }
  return true;
}

}  // namespace fw::render
