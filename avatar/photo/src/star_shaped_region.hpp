#pragma once
// A region as a star-shaped outline about a centre: its reach along each of
// many rays, evened out across neighbouring rays and filled back in.
//
// A head seen from the front is star-shaped about a point between the eyes
// and the ears: every ray from there leaves it once. A colour segmentation
// is not: it leaves holes where the jaw meets the neck, and thin scraps of
// background whose colours match hair. Read as reaches along rays, a hole
// inside the head is skipped (the reach is where the region last ends going
// out), a scrap a few rays wide is an outlier among its neighbours' reaches,
// and the region filled back from them has neither.
#include <vector>

#include <opencv2/core.hpp>

namespace fw::photo {

/// `region` (CV_8U, 0 or 255) with every hole filled: the background parts
/// that do not touch the image's border.
cv::Mat fill_holes(const cv::Mat& region);

/// The reach of `region` (CV_8U, nonzero inside) along `rays` rays from
/// `centre` (pixels), ray k at angle 2 pi k / rays counter-clockwise from +x
/// with y up (image rows run down): the farthest point of the region's part
/// that is connected to the centre along the ray, allowing gaps up to
/// `max_gap` pixels. 0 where the centre itself is outside.
std::vector<float> ray_reach(const cv::Mat& region, cv::Point2f centre, int rays, float max_gap);

/// Each reach replaced by the median of the `half_window` rays either side
/// and itself (the rays wrap around).
std::vector<float> median_across_rays(const std::vector<float>& reach, int half_window);

/// The region the reaches outline, filled (CV_8U 255 inside) at `size`,
/// with `scale` pixels of the output per pixel of the reaches.
cv::Mat fill_reach(const std::vector<float>& reach, cv::Point2f centre, cv::Size size, float scale);

}  // namespace fw::photo
