#pragma once
// Limits on the photos facewire accepts, checked before any decoding.
#include <cstddef>

namespace fw::photo {

inline constexpr std::size_t kMaxPhotoBytes = 10 * 1000 * 1000;   ///< 10 MB
inline constexpr std::size_t kMaxPhotoPixels = 40 * 1000 * 1000;  ///< 40 megapixels
/// Faces narrower than this (ear to ear along the jaw line, photo pixels)
/// carry too little detail for a texture. 100 px and more make a good one.
inline constexpr int kMinFaceWidthPx = 40;

/// OpenCV reads its own pixel limit (OPENCV_IO_MAX_IMAGE_PIXELS) from the
/// environment once, when its library loads, so it cannot be set from main.
/// Call this first thing in main: if the variable is not already our limit,
/// it sets it and re-executes the program (same arguments) so that OpenCV
/// starts with it. Returns normally when the limit is in force; if the
/// re-execution itself fails it returns too, leaving facewire's own header
/// checks as the guard.
void enforce_decoder_pixel_limit(char** argv);

}  // namespace fw::photo
