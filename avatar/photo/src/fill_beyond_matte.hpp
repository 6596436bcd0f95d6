#pragma once
// Colour for the texels a matte leaves out.
#include <opencv2/core.hpp>

namespace fw::photo {

/// BGRA: `texture` (BGR) with `alpha` as alpha, and every texel not fully
/// inside `matte` recoloured from the nearest texels that are (pull-push
/// over an image pyramid). Filtering and mipmaps mix texels across the
/// matte's edge; this way they mix hair with hair, never with background,
/// and a part the alpha shows beyond the matte (the neck) takes the colours
/// nearest to it.
cv::Mat fill_beyond_matte(const cv::Mat& texture, const cv::Mat& matte, const cv::Mat& alpha);

}  // namespace fw::photo
