#include "exif_orientation.hpp"

#include <cstring>

namespace fw::photo {
namespace {

// TIFF's two byte orders ("II" little-endian, "MM" big-endian); every read
// is bounds-checked against the payload, which comes from outside.
struct TiffReader {
  std::span<const std::uint8_t> bytes;
  bool little_endian;

  bool u16(std::size_t at, std::uint16_t& out) const {
    if (at + 2 > bytes.size()) return false;
    out = little_endian ? static_cast<std::uint16_t>(bytes[at] | bytes[at + 1] << 8)
                        : static_cast<std::uint16_t>(bytes[at] << 8 | bytes[at + 1]);
    return true;
  }
  bool u32(std::size_t at, std::uint32_t& out) const {
    std::uint16_t a = 0, b = 0;
    if (!u16(at, a) || !u16(at + 2, b)) return false;
    out = little_endian ? (static_cast<std::uint32_t>(b) << 16 | a) : (static_cast<std::uint32_t>(a) << 16 | b);
    return true;
  }
};

}  // namespace

int exif_orientation(std::span<const std::uint8_t> app1_payload) {
  constexpr std::uint16_t kOrientationTag = 0x0112, kShortType = 3;
  if (app1_payload.size() < 6 || std::memcmp(app1_payload.data(), "Exif\0\0", 6) != 0) return 1;
  const auto tiff = app1_payload.subspan(6);
  if (tiff.size() < 8) return 1;
  TiffReader reader{tiff, tiff[0] == 'I' && tiff[1] == 'I'};
  if (!reader.little_endian && !(tiff[0] == 'M' && tiff[1] == 'M')) return 1;
  std::uint32_t ifd = 0;
  std::uint16_t entries = 0;
  if (!reader.u32(4, ifd) || !reader.u16(ifd, entries)) return 1;
  for (std::uint32_t i = 0; i < entries; ++i) {
    const std::size_t entry = static_cast<std::size_t>(ifd) + 2 + 12 * static_cast<std::size_t>(i);
    std::uint16_t tag = 0, type = 0, value = 0;
    if (!reader.u16(entry, tag) || !reader.u16(entry + 2, type)) return 1;
    if (tag != kOrientationTag) continue;
    // A SHORT value sits in the first two bytes of the entry's value field.
    if (type != kShortType || !reader.u16(entry + 8, value) || value < 1 || value > 8) return 1;
    return value;
  }
  return 1;
}

void turn_upright(cv::Mat& image, int orientation) {
  // EXIF 2..8: mirrored, upside down, mirrored upside down, then the four
  // that swap rows and columns (a transpose, then a flip).
  switch (orientation) {
    case 2: cv::flip(image, image, 1); break;
    case 3: cv::flip(image, image, -1); break;
    case 4: cv::flip(image, image, 0); break;
    case 5: cv::transpose(image, image); break;
    case 6: cv::transpose(image, image); cv::flip(image, image, 1); break;
    case 7: cv::transpose(image, image); cv::flip(image, image, -1); break;
    case 8: cv::transpose(image, image); cv::flip(image, image, 0); break;
    default: break;
  }
}

}  // namespace fw::photo
