#pragma once
// A photo made small for its upload: decoded (JPEG, PNG or WebP), scaled
// down so its longer side is at most kMaxUploadSide pixels, and re-encoded
// as a JPEG of about kTargetUploadBytes, so that it crosses even a slow link
// in reasonable time (30 KB take 25 s at 9.6 kbit/s). The server's face
// finder still gets 100+ pixels between the eyes of a portrait.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fw/model/image.hpp"

namespace fw::client {

inline constexpr int kMaxUploadSide = 640;
inline constexpr std::size_t kTargetUploadBytes = 30 * 1024;
/// Photos larger than this on a side are refused before decoding.
inline constexpr int kMaxPhotoSide = 12000;
inline constexpr std::size_t kMaxPhotoFileBytes = 64 * 1024 * 1024;

struct DownsizedPhoto {
  std::vector<std::uint8_t> jpeg;
  int width = 0, height = 0;  ///< of the JPEG
  int quality = 0;            ///< the JPEG quality chosen
};

/// @param[in]  photo  the file's bytes (JPEG, PNG or WebP)
/// @param[out] out    the JPEG to upload, at most kTargetUploadBytes + 10%
/// @param[out] error  what is wrong with the photo and what to do
bool downsize_photo(std::span<const std::uint8_t> photo, DownsizedPhoto& out, std::string& error);

/// `image` shrunk by an area average so that neither side exceeds `max_side`
/// (returned unchanged when it already fits). Box filtering keeps the fine
/// detail of a large photo from aliasing, which bilinear sampling would not.
model::RgbaImage shrink_to_fit(const model::RgbaImage& image, int max_side);

}  // namespace fw::client
