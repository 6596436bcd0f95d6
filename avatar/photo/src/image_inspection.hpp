#pragma once
// Looking at a photo's bytes before decoding it: what format it is, how
// large it says it is, whether it is all there.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "fw/photo/photo_limits.hpp"
#include "fw/photo/prep_error.hpp"

namespace fw::photo {

enum class PhotoFormat { jpeg, png, webp };

struct PhotoHeader {
  PhotoFormat format;
  int width = 0;
  int height = 0;
};

/// Checks signature (JPEG, PNG or WebP; other images are named in the
/// error), byte size, pixel count from the header, and that the file is
/// complete (PNG chunks through IEND, JPEG through its end-of-image marker,
/// WebP through the size its RIFF header gives). `max_pixels` may be lower
/// than kMaxPhotoPixels (a server's own limit), never higher: the decoder
/// refuses more.
/// @return the header, or nullopt with `error` set
std::optional<PhotoHeader> inspect_photo(std::span<const std::uint8_t> bytes, PrepError& error,
                                         std::size_t max_pixels = kMaxPhotoPixels);

}  // namespace fw::photo
