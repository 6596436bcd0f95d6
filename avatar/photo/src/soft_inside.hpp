#pragma once
// A weight that fades out towards a mask's edge.
//
// A matte thresholded to "the person's own colour" has a ragged edge at
// texel scale. Where the texture switches at that edge from the photo to
// something else (colours filled from inside, the neck's shadow), the
// switch shows every step of it, and a turned head stretches each step over
// several pixels into a sawtooth. Blending across the edge hides the steps;
// the weight reaches zero at the mask's edge, so nothing from outside it is
// blended in.
#include <opencv2/core.hpp>

namespace fw::photo {

/// CV_32F, `mask`'s size: 1 deeper than about `texels` inside `mask`
/// (CV_8U, non-zero inside), easing to 0 at its edge, 0 outside.
cv::Mat soft_inside(const cv::Mat& mask, int texels);

}  // namespace fw::photo
