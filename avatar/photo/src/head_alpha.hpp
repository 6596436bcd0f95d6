#pragma once
// The face texture's alpha: what of the head shell and the face is shown.
//
// The shell's silhouette is the person's outline (head_matte.hpp), so the
// alpha need not cut it: it is solid out to a little beyond the outline, and
// the texels between the person's matte and the outline take the colours of
// the person's edge (fill_beyond_matte.hpp). A side of the head seen turned
// then shows hair where the photo saw the silhouette, not a cut-out band of
// the matte's soft edge. Below the jaw the photo shows clothes as often as a
// neck: the shell's neck is shown whole, in the jaw's colours, down out of
// the frame as a portrait's neck runs (cut short by the alpha, the neck's
// back, which takes the jaw's colour, would show below its cut front).
#include <span>

#include <glm/vec2.hpp>

#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// @param[in] person     the person's matte (head_matte), CV_8U over `frame`
/// @param[in] outline    the package's head_outline: the silhouette on each of
///                       `head`'s rays
/// @param[in] fitted_rim the face's rim as fitted (model::face_rim_loop's
///                       vertices, fitted): the shell reaches past it
/// @param[in] head       the generic head shell (its centre and rays)
/// @return CV_8U, `person`'s size: 255 where the head shows, soft at the outline
cv::Mat head_alpha(const cv::Mat& person, std::span<const float> outline, std::span<const glm::vec2> fitted_rim,
                   const model::HeadShell& head, const model::TextureFrame& frame);

}  // namespace fw::photo
