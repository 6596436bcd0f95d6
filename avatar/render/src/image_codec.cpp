#include "fw/render/image_codec.hpp"

#include <cstring>

#include <png.h>
#include <webp/decode.h>

namespace fw::render {
namespace {

bool size_ok(int width, int height, int max_side, std::string& error) {
  if (width <= 0 || height <= 0 || width > max_side || height > max_side) {
    error = "image of " + std::to_string(width) + "x" + std::to_string(height) + " pixels; at most " +
            std::to_string(max_side) + " on a side is accepted";
    return false;
  }
  return true;
}

bool decode_webp(std::span<const std::uint8_t> bytes, int max_side, model::RgbaImage& image, std::string& error) {
  int width = 0, height = 0;
  if (!WebPGetInfo(bytes.data(), bytes.size(), &width, &height)) {
    error = "damaged WebP image";
    return false;
  }
  if (!size_ok(width, height, max_side, error)) return false;
  model::RgbaImage decoded(width, height);
  if (!WebPDecodeRGBAInto(bytes.data(), bytes.size(), decoded.pixels.data(), decoded.pixels.size(), width * 4)) {
    error = "damaged WebP image";
    return false;
  }
  image = std::move(decoded);
  return true;
}

bool decode_png(std::span<const std::uint8_t> bytes, int max_side, model::RgbaImage& image, std::string& error) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size())) {
    error = std::string("damaged PNG image: ") + png.message;
    return false;
  }
  if (!size_ok(static_cast<int>(png.width), static_cast<int>(png.height), max_side, error)) {
    png_image_free(&png);
    return false;
  }
  png.format = PNG_FORMAT_RGBA;
  model::RgbaImage decoded(static_cast<int>(png.width), static_cast<int>(png.height));
  if (!png_image_finish_read(&png, nullptr, decoded.pixels.data(), 0, nullptr)) {
    error = std::string("damaged PNG image: ") + png.message;
    return false;
  }
  image = std::move(decoded);
  return true;
}

}  // namespace

bool decode_image(std::span<const std::uint8_t> bytes, int max_side, model::RgbaImage& image, std::string& error) {
  static constexpr std::uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() >= 12 && std::memcmp(bytes.data(), "RIFF", 4) == 0 && std::memcmp(bytes.data() + 8, "WEBP", 4) == 0)
    return decode_webp(bytes, max_side, image, error);
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPng, 8) == 0) return decode_png(bytes, max_side, image, error);
  error = "not a WebP or PNG image";
  return false;
}

}  // namespace fw::render
