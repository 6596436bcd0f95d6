#pragma once
// Limits on the photos facewire accepts, checked before any decoding.
#include <cstddef>

namespace fw::photo {

inline constexpr std::size_t kMaxPhotoBytes = 10 * 1000 * 1000;   ///< 10 MB
inline constexpr std::size_t kMaxPhotoPixels = 40 * 1000 * 1000;  ///< 40 megapixels
/// Faces narrower than this (ear to ear along the jaw line, photo pixels)
/// carry too little detail for a texture. 100 px and more make a good one.
inline constexpr int kMinFaceWidthPx = 40;

}  // namespace fw::photo
