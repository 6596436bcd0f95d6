#pragma once
// Encoding the prepared layers into package members.
#include <opencv2/core.hpp>

#include "fw/model/avatar_package.hpp"

namespace fw::photo {

/// WebP, lossy at `quality` (1..100) or lossless when quality > 100; alpha
/// (a fourth channel) is kept. `image` is BGR or BGRA.
model::PackageImage encode_webp(const cv::Mat& image, int quality);

}  // namespace fw::photo
