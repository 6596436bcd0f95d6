#pragma once
// Looking at a photo's bytes before decoding it: what format it is, how
// large it says it is, whether it is all there.
#include <cstdint>
#include <optional>
#include <span>

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
/// WebP through the size its RIFF header gives).
/// @return the header, or nullopt with `error` set
std::optional<PhotoHeader> inspect_photo(std::span<const std::uint8_t> bytes, PrepError& error);

}  // namespace fw::photo
