#pragma once
// Colour for the texels a matte leaves out.
#include <opencv2/core.hpp>

namespace fw::photo {

/// BGRA: `texture` (BGR) with `matte` as alpha, and every texel not fully
/// inside the matte recoloured from the nearest texels that are (pull-push
/// over an image pyramid). Filtering and mipmaps mix texels across the
/// matte's edge; this way they mix hair with hair, never with background.
cv::Mat fill_beyond_matte(const cv::Mat& texture, const cv::Mat& matte);

}  // namespace fw::photo
