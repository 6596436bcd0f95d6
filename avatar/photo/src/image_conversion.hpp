#pragma once
// Between OpenCV's BGR(A) matrices and facewire's RGBA images.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "fw/model/image.hpp"

namespace fw::photo {

inline model::RgbaImage to_rgba_image(const cv::Mat& bgr_or_bgra) {
  model::RgbaImage image(bgr_or_bgra.cols, bgr_or_bgra.rows);
  cv::Mat rgba(bgr_or_bgra.rows, bgr_or_bgra.cols, CV_8UC4, image.pixels.data());
  cv::cvtColor(bgr_or_bgra, rgba, bgr_or_bgra.channels() == 4 ? cv::COLOR_BGRA2RGBA : cv::COLOR_BGR2RGBA);
  return image;
}

inline cv::Mat to_bgr_mat(const model::RgbaImage& image) {
  const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.pixels.data()));
  cv::Mat bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  return bgr;
}

}  // namespace fw::photo
