#include "image_inspection.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "fw/photo/photo_limits.hpp"

namespace fw::photo {
namespace {

std::uint32_t be32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
         static_cast<std::uint32_t>(p[2]) << 8 | p[3];
}
std::uint16_t be16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] << 8 | p[1]); }

bool starts_with(std::span<const std::uint8_t> b, const char* magic, std::size_t n, std::size_t at = 0) {
  return b.size() >= at + n && std::memcmp(b.data() + at, magic, n) == 0;
}

std::optional<PhotoHeader> fail(PrepError& error, PrepErrorCode code, std::string message) {
  error = {code, std::move(message)};
  return std::nullopt;
}

// Names the formats people most often send instead of JPEG, PNG or WebP.
const char* other_image_format(std::span<const std::uint8_t> b) {
  if (starts_with(b, "GIF8", 4)) return "GIF";
  if (starts_with(b, "BM", 2)) return "BMP";
  if (starts_with(b, "II*\0", 4) || starts_with(b, "MM\0*", 4)) return "TIFF";
  if (starts_with(b, "ftypheic", 8, 4) || starts_with(b, "ftypmif1", 8, 4) || starts_with(b, "ftypheix", 8, 4)) return "HEIC";
  if (starts_with(b, "ftypavif", 8, 4)) return "AVIF";
  return nullptr;
}

std::optional<PhotoHeader> inspect_png(std::span<const std::uint8_t> b, PrepError& error) {
  PhotoHeader header{PhotoFormat::png};
  std::size_t at = 8;
  bool first = true;
  while (true) {
    if (b.size() < at + 12) return fail(error, PrepErrorCode::truncated, "the PNG file is truncated (it ends before its last chunk); send the whole file");
    const std::uint32_t length = be32(b.data() + at);
    const std::uint8_t* type = b.data() + at + 4;
    if (length > b.size() - at - 12) return fail(error, PrepErrorCode::truncated, "the PNG file is truncated (a chunk runs past its end); send the whole file");
    if (first) {
      if (std::memcmp(type, "IHDR", 4) != 0 || length != 13) return fail(error, PrepErrorCode::undecodable, "the PNG file is damaged (no header chunk)");
      header.width = static_cast<int>(std::min<std::uint32_t>(be32(b.data() + at + 8), 1u << 30));
      header.height = static_cast<int>(std::min<std::uint32_t>(be32(b.data() + at + 12), 1u << 30));
      first = false;
    }
    if (std::memcmp(type, "IEND", 4) == 0) return header;
    at += 12 + length;
  }
}

std::uint32_t le32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[3]) << 24 | static_cast<std::uint32_t>(p[2]) << 16 |
         static_cast<std::uint32_t>(p[1]) << 8 | p[0];
}
std::uint32_t le24(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[1]) << 8 | p[0];
}

// A WebP file: "RIFF", the bytes that follow, "WEBP", then the first chunk,
// whose header gives the size: VP8 (lossy), VP8L (lossless) or VP8X
// (extended: alpha, animation, metadata).
std::optional<PhotoHeader> inspect_webp(std::span<const std::uint8_t> b, PrepError& error) {
  PhotoHeader header{PhotoFormat::webp};
  if (b.size() < 30) return fail(error, PrepErrorCode::truncated, "the WebP file is truncated (it ends inside its header); send the whole file");
  if (std::uint64_t{le32(b.data() + 4)} + 8 > b.size())
    return fail(error, PrepErrorCode::truncated, "the WebP file is truncated (it ends before its last chunk); send the whole file");
  const std::uint8_t* chunk = b.data() + 12;
  const std::uint8_t* data = chunk + 8;
  if (std::memcmp(chunk, "VP8X", 4) == 0) {
    if (data[0] & 0x02) return fail(error, PrepErrorCode::unsupported_format, "the WebP image is animated; send a still photo");
    header.width = static_cast<int>(le24(data + 4) + 1);
    header.height = static_cast<int>(le24(data + 7) + 1);
  } else if (std::memcmp(chunk, "VP8L", 4) == 0) {
    if (data[0] != 0x2f) return fail(error, PrepErrorCode::undecodable, "the WebP file is damaged (bad lossless signature)");
    const std::uint32_t bits = le32(data + 1);
    header.width = static_cast<int>((bits & 0x3fff) + 1);
    header.height = static_cast<int>(((bits >> 14) & 0x3fff) + 1);
  } else if (std::memcmp(chunk, "VP8 ", 4) == 0) {
    if (data[3] != 0x9d || data[4] != 0x01 || data[5] != 0x2a)
      return fail(error, PrepErrorCode::undecodable, "the WebP file is damaged (bad frame start)");
    header.width = (data[6] | data[7] << 8) & 0x3fff;
    header.height = (data[8] | data[9] << 8) & 0x3fff;
  } else {
    return fail(error, PrepErrorCode::undecodable, "the WebP file is damaged (unknown first chunk)");
  }
  return header;
}

std::optional<PhotoHeader> inspect_jpeg(std::span<const std::uint8_t> b, PrepError& error) {
  PhotoHeader header{PhotoFormat::jpeg};
  std::size_t at = 2;
  while (true) {
    // Markers may be padded with fill bytes 0xFF.
    while (at < b.size() && b[at] == 0xFF && at + 1 < b.size() && b[at + 1] == 0xFF) ++at;
    if (at + 4 > b.size()) return fail(error, PrepErrorCode::truncated, "the JPEG file is truncated (it ends inside its header); send the whole file");
    if (b[at] != 0xFF) return fail(error, PrepErrorCode::undecodable, "the JPEG file is damaged (a marker is missing)");
    const std::uint8_t marker = b[at + 1];
    if (marker == 0xD9) return fail(error, PrepErrorCode::undecodable, "the JPEG file has no image data");
    // Restart markers and TEM stand alone, with no length (T.81 B.1.1.3), as
    // libjpeg reads them: reading two bytes after one as a length would skip
    // a frame header the decoder sees, and a bomb's size with it.
    if ((marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) {
      at += 2;
      continue;
    }
    const std::uint16_t length = be16(b.data() + at + 2);
    if (length < 2 || at + 2 + length > b.size()) return fail(error, PrepErrorCode::truncated, "the JPEG file is truncated (a segment runs past its end); send the whole file");
    const bool start_of_frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (start_of_frame) {
      if (length < 7) return fail(error, PrepErrorCode::undecodable, "the JPEG file is damaged (short frame header)");
      header.height = be16(b.data() + at + 5);
      header.width = be16(b.data() + at + 7);
    }
    if (marker == 0xDA) {  // start of scan: entropy-coded data follows up to the end-of-image marker
      if (header.width == 0 || header.height == 0) return fail(error, PrepErrorCode::undecodable, "the JPEG file is damaged (no frame size)");
      for (std::size_t i = b.size() - 2; i > at; --i)
        if (b[i] == 0xFF && b[i + 1] == 0xD9) return header;
      return fail(error, PrepErrorCode::truncated, "the JPEG file is truncated (its image data is cut off); send the whole file");
    }
    at += 2 + length;
  }
}

/// A pixel count as a person reads it: "40 megapixels", or the pixels
/// themselves when the limit is no whole number of megapixels.
std::string pixels_text(std::size_t pixels) {
  if (pixels % 1000000 == 0) return std::to_string(pixels / 1000000) + " megapixels";
  return std::to_string(pixels) + " pixels";
}

}  // namespace

std::optional<PhotoHeader> inspect_photo(std::span<const std::uint8_t> bytes, PrepError& error,
                                         std::size_t max_pixels) {
  max_pixels = std::min(max_pixels, kMaxPhotoPixels);
  if (bytes.size() > kMaxPhotoBytes)
    return fail(error, PrepErrorCode::too_many_bytes,
                "the photo is " + std::to_string(bytes.size() / 1000000) + " MB; at most 10 MB is accepted: send a smaller JPEG");
  std::optional<PhotoHeader> header;
  static constexpr char kPng[] = "\x89PNG\r\n\x1a\n";
  if (starts_with(bytes, kPng, 8)) header = inspect_png(bytes, error);
  else if (starts_with(bytes, "\xFF\xD8\xFF", 3)) header = inspect_jpeg(bytes, error);
  else if (starts_with(bytes, "RIFF", 4) && starts_with(bytes, "WEBP", 4, 8)) header = inspect_webp(bytes, error);
  else if (const char* other = other_image_format(bytes))
    return fail(error, PrepErrorCode::unsupported_format,
                std::string("the photo is a ") + other + " image; facewire reads JPEG, PNG and WebP: convert it first");
  else
    return fail(error, PrepErrorCode::not_an_image, "the file is not an image (not JPEG, PNG or WebP); send a photo of a face");
  if (!header) return std::nullopt;
  if (header->width <= 0 || header->height <= 0)
    return fail(error, PrepErrorCode::undecodable, "the image header gives no size; the file is damaged");
  const auto pixels = static_cast<std::uint64_t>(header->width) * static_cast<std::uint64_t>(header->height);
  // Read from the header, before any decoding: a small PNG may declare a
  // picture that takes hundreds of megabytes and seconds to decode.
  if (pixels > max_pixels)
    return fail(error, PrepErrorCode::too_many_pixels,
                "the photo is " + std::to_string(header->width) + "x" + std::to_string(header->height) +
                    " pixels; at most " + pixels_text(max_pixels) +
                    " is accepted: scale it down (a face needs no more than a few megapixels)");
  return header;
}

}  // namespace fw::photo
