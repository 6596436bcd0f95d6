#pragma once
// The band of the face texture just inside the head's outline, smoothed
// around the head.
//
// The head shell takes the photo's colours out to the person's silhouette,
// where the photo saw the surface edge-on: there each texel stands for a
// strip of the side of the head, which a turned head shows. Every strand of
// hair, hinge of a pair of glasses or edge between hair and skin on the
// outline then ran back across the side as a streak. Blurring the band
// around the head (not across it), from nothing at its inner edge to about
// 45 degrees at the silhouette, keeps where the hair ends and turns those
// streaks into the smooth sides a head has. Seen from the front, only the
// outermost texels of hair soften; the face itself is left sharp.
#include <span>

#include <glm/vec2.hpp>
#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"

namespace fw::photo {

/// @param[in,out] bgra      the face texture (CV_8UC4), its alpha unchanged
/// @param[in] outline       the silhouette's radius on each of the head's rays
/// @param[in] inner         where on each ray the band begins: the radius
///                          whose colour the head's back takes
///                          (model::unseen_colour_radii), or the face's rim
///                          where that lies further out
/// @param[in] centre        the head shell's centre (model units)
/// The neck's rays (model::kNeckRaySine), whose silhouette lies below the
/// texture, are left as they are.
void smooth_outline_band(cv::Mat& bgra, std::span<const float> outline, std::span<const float> inner,
                         glm::vec2 centre, const model::TextureFrame& frame);

}  // namespace fw::photo
