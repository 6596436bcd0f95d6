#include "fill_beyond_matte.hpp"

#include <algorithm>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "soft_inside.hpp"

namespace fw::photo {
namespace {

// A texel is the person's own colour only well inside the soft edge, and
// not in the last texels along it: resampling the photo mixed those with
// what stood behind the person (a strand of hair against a flag is half flag).
constexpr int kSolidAlpha = 250;
constexpr int kEdgeTexelsPer320 = 2;

}  // namespace

cv::Mat fill_beyond_matte(const cv::Mat& texture, const cv::Mat& matte, const cv::Mat& alpha) {
  cv::Mat colour, weight;
  texture.convertTo(colour, CV_32FC3, 1.0 / 255);
  cv::Mat solid = matte >= kSolidAlpha;
  const int edge = std::max(1, kEdgeTexelsPer320 * texture.cols / 320);
  cv::erode(solid, solid, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * edge + 1, 2 * edge + 1)));
  solid.convertTo(weight, CV_32F, 1.0 / 255);
  cv::Mat weight3;
  cv::merge(std::vector<cv::Mat>{weight, weight, weight}, weight3);
  // Pull: weighted colour and weight averaged down the pyramid.
  std::vector<cv::Mat> colours{colour.mul(weight3)}, weights{weight};
  while (colours.back().cols > 2 && colours.back().rows > 2) {
    cv::Mat c, w;
    cv::pyrDown(colours.back(), c);
    cv::pyrDown(weights.back(), w);
    colours.push_back(c);
    weights.push_back(w);
  }
  // Push: each level's holes filled from the level below it.
  cv::Mat filled;
  for (std::size_t l = colours.size(); l-- > 0;) {
    cv::Mat w3;
    cv::merge(std::vector<cv::Mat>{weights[l], weights[l], weights[l]}, w3);
    cv::Mat normalised;
    cv::divide(colours[l], cv::max(w3, 1e-6), normalised);
    if (filled.empty()) {
      filled = normalised;
      continue;
    }
    cv::Mat up;
    cv::pyrUp(filled, up, colours[l].size());
    const cv::Mat trust = cv::min(w3 * 4.0, 1.0);  // enough weight nearby: the level's own average
    filled = normalised.mul(trust) + up.mul(cv::Scalar::all(1.0) - trust);
  }
  // The photo's colours fade into the filled ones over a few texels inside
  // the matte, not at its ragged edge (soft_inside.hpp).
  const cv::Mat own = soft_inside(solid, edge);
  cv::Mat own3;
  cv::merge(std::vector<cv::Mat>{own, own, own}, own3);
  const cv::Mat blended = filled + (colour - filled).mul(own3);
  cv::Mat filled_bgr;
  blended.convertTo(filled_bgr, CV_8UC3, 255.0);
  cv::Mat bgra;
  cv::cvtColor(filled_bgr, bgra, cv::COLOR_BGR2BGRA);
  cv::insertChannel(alpha, bgra, 3);
  return bgra;
}

}  // namespace fw::photo
