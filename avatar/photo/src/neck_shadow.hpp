#pragma once
// The neck in the jaw's shadow.
//
// Below the jaw the texture's colours are not the photo's (a collar or the
// shoulders stand there as often as the neck): the neck takes the jaw's
// colours (fill_beyond_matte). Coloured like the jaw and lit like it, it
// would leave the chin no edge, and an observer (or dlib's shape predictor)
// would lose the jaw line. Portrait light comes from above the face, so the
// jaw casts its shadow on the neck: darkest right under the jaw, lighter
// further down.
#include <opencv2/core.hpp>

#include "fw/model/generic_face.hpp"
#include "mesh_fitting.hpp"

namespace fw::photo {

/// Darkens, in place, the texels of `bgra` below the jaw's lower part
/// (landmarks 3..13) that are not the person's own (`matte` under full):
/// to about half their brightness just under the jaw line, easing to four
/// fifths a third of a unit below it; beside the jaw's lower part, and
/// towards the person's own colours, the shadow fades out.
void shade_neck(cv::Mat& bgra, const cv::Mat& matte, const ModelLandmarks& landmarks,
                const model::TextureFrame& frame);

}  // namespace fw::photo
