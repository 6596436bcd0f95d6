#pragma once
// Encoding and shrinking the images of avatar packages (libwebp), for
// the demo faces and the preview packages.
#include <optional>

#include "fw/model/avatar_package.hpp"
#include "fw/model/image.hpp"

namespace fw::server {

/// RGBA pixels as a WebP member (alpha kept), lossy at `quality` 1..100.
model::PackageImage encode_package_image(const model::RgbaImage& image, int quality);

/// The member decoded and scaled so that its longer side is at most
/// `max_side` pixels, then encoded again at `quality`; nullopt if it does
/// not decode.
std::optional<model::PackageImage> shrink_package_image(const model::PackageImage& image, int max_side, int quality);

}  // namespace fw::server
