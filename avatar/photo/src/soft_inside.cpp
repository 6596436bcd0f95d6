#include "soft_inside.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace fw::photo {

cv::Mat soft_inside(const cv::Mat& mask, int texels) {
  const int radius = std::max(1, texels);
  // Shrunk by the radius and blurred by half of it, the weight has fallen
  // to about 2 % at the edge; cut to the mask, it is exactly 0 beyond.
  cv::Mat inside = mask != 0;
  cv::Mat shrunk;
  cv::erode(inside, shrunk, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * radius + 1, 2 * radius + 1)));
  cv::Mat weight;
  shrunk.convertTo(weight, CV_32F, 1.0 / 255);
  cv::GaussianBlur(weight, weight, cv::Size(), radius / 2.0);
  weight.setTo(0.0f, inside == 0);
  return weight;
}

}  // namespace fw::photo
