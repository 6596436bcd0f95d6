#pragma once
// Faces and their 68 landmarks in a photo, with dlib: the HOG frontal face
// detector on a reduced copy (fast on large photos; OpenCV's face cascade
// when it finds nothing), the 68-point shape predictor on the
// full-resolution image.
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

/// A face the detector found, in the view of the photo it was found in: the
/// photo itself, or the photo turned by a multiple of 45 degrees when the
/// face is rolled too far for the detector to see it upright.
struct FoundFace {
  cv::Rect box;                  ///< the face's bounding box in photo pixels
  cv::Matx23d photo_to_view{1, 0, 0, 0, 1, 0};  ///< photo pixels to the detector's view
  cv::Rect view_box;             ///< the detector's box in that view
  double turn_deg = 0;           ///< how far the view is turned, counterclockwise
  bool by_fallback = false;      ///< found by OpenCV's cascade, not dlib's detector
};

class FaceFinder {
 public:
  /// Loads the shape predictor (about 95 MB, a second or so): once per process.
  static std::unique_ptr<FaceFinder> load(const std::optional<std::filesystem::path>& model_path, PrepError& error);
  ~FaceFinder();

  /// The faces in the photo, largest first. The detector looks at the photo
  /// as it is, then, unless it found a face there confidently, turned by 90,
  /// -90 and 180 degrees (a phone photo stored sideways or upside down) and
  /// by the odd multiples of 45 degrees (a head rolled far over), and keeps
  /// the faces of the view with the most confident one. When no view shows
  /// one, OpenCV's face cascade looks at the photo as it is. Not thread-safe:
  /// dlib's detector keeps scratch state.
  std::vector<FoundFace> detect(const cv::Mat& gray);

  /// The 68 landmarks of `face`, in photo pixels, found on the
  /// full-resolution image: a first pass in the detector's box (in its
  /// view), a second on the face turned upright at a fixed size in a box
  /// placed from the first pass's eyes, so that any roll is taken out.
  PhotoLandmarks landmarks(const cv::Mat& gray, const FoundFace& face) const;

 private:
  FaceFinder();
  /// The detector's boxes in `view`, largest first, and the best one's
  /// confidence; boxes below kMinConfidence only when nothing scores higher.
  std::vector<cv::Rect> detect_in(const cv::Mat& view, double& best_confidence);
  /// OpenCV's face cascade on the upright photo, its boxes framed like
  /// dlib's, largest first: for when dlib's detector sees nothing.
  std::vector<cv::Rect> detect_with_fallback(const cv::Mat& gray);
  PhotoLandmarks predict(const cv::Mat& gray, const cv::Matx23d& photo_to_patch, cv::Size size,
                         const cv::Rect2d& box) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fw::photo
