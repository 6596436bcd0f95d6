#pragma once
// Faces and their 68 landmarks in a photo, with dlib: the HOG frontal face
// detector on a reduced copy (fast on large photos), the 68-point shape
// predictor on the full-resolution image.
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <opencv2/core.hpp>

#include "fw/model/landmark_template.hpp"
#include "fw/photo/prep_error.hpp"

namespace fw::photo {

using PhotoLandmarks = std::array<glm::vec2, model::kLandmarkCount>;  ///< photo pixels

class FaceFinder {
 public:
  /// Loads the shape predictor (about 95 MB, a second or so): once per process.
  static std::unique_ptr<FaceFinder> load(const std::optional<std::filesystem::path>& model_path, PrepError& error);
  ~FaceFinder();

  /// Face boxes in full-resolution photo pixels, largest first.
  /// Not thread-safe: dlib's detector keeps scratch state.
  std::vector<cv::Rect> detect(const cv::Mat& gray);

  /// The 68 landmarks of the face in `box`, found on the full-resolution
  /// image: a first pass in the detector's box, a second on the face turned
  /// upright at a fixed size in a box placed from the first pass's eyes.
  PhotoLandmarks landmarks(const cv::Mat& gray, const cv::Rect& box) const;

 private:
  FaceFinder();
  PhotoLandmarks predict(const cv::Mat& gray, const cv::Matx23d& photo_to_patch, cv::Size size,
                         const cv::Rect2d& box) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fw::photo
