#include "face_finder.hpp"

#include <algorithm>

#include <dlib/image_processing.h>
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/opencv.h>
#include <opencv2/imgproc.hpp>

#include "fw/photo/landmark_model.hpp"

namespace fw::photo {
namespace {

// The detector finds faces from about 80 px up. It looks at a copy whose
// longer side is this: large photos shrink (fast), small ones grow (up to
// kMaxUpscale, so a 40 px face in a small photo is still found). A large
// photo whose face is too small at that size gets a second look at twice it.
constexpr int kDetectionSide = 640;
constexpr double kMaxUpscale = 4.0;
// The shape predictor is given the face at least this wide (upscaled from
// the full-resolution photo when smaller), since its landmarks are whole
// pixels of the image it sees.
constexpr int kLandmarkFaceWidth = 200;

}  // namespace

struct FaceFinder::Impl {
  dlib::frontal_face_detector detector = dlib::get_frontal_face_detector();
  dlib::shape_predictor predictor;
};

FaceFinder::FaceFinder() : impl_(std::make_unique<Impl>()) {}
FaceFinder::~FaceFinder() = default;

std::unique_ptr<FaceFinder> FaceFinder::load(const std::optional<std::filesystem::path>& model_path, PrepError& error) {
  std::filesystem::path tried;
  const auto path = find_landmark_model(model_path, tried);
  if (!path) {
    error = {PrepErrorCode::model_missing, "the 68-point landmark model is not at " + tried.string() +
                                               " (install Debian's libdlib-data, or give its path with --landmark-model)"};
    return nullptr;
  }
  std::unique_ptr<FaceFinder> finder(new FaceFinder());
  try {
    dlib::deserialize(path->string()) >> finder->impl_->predictor;
  } catch (const std::exception& e) {
    error = {PrepErrorCode::model_missing, "cannot load the landmark model " + path->string() + ": " + e.what()};
    return nullptr;
  }
  if (finder->impl_->predictor.num_parts() != model::kLandmarkCount) {
    error = {PrepErrorCode::model_missing, path->string() + " is not a 68-point landmark model"};
    return nullptr;
  }
  return finder;
}

std::vector<cv::Rect> FaceFinder::detect(const cv::Mat& gray) {
  std::vector<cv::Rect> boxes;
  for (const int side : {kDetectionSide, 2 * kDetectionSide}) {
    const double scale = std::min(kMaxUpscale, static_cast<double>(side) / std::max(gray.cols, gray.rows));
    if (side > kDetectionSide && scale >= 1.0) break;  // the first look already saw it at full size
    cv::Mat small;
    if (scale < 1.0) cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_AREA);
    else if (scale > 1.0) cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_LINEAR);
    else small = gray;
    const dlib::cv_image<unsigned char> image(small);
    for (const dlib::rectangle& r : impl_->detector(image)) {
      boxes.emplace_back(static_cast<int>(r.left() / scale), static_cast<int>(r.top() / scale),
                         static_cast<int>(r.width() / scale), static_cast<int>(r.height() / scale));
    }
    if (!boxes.empty()) break;
  }
  std::sort(boxes.begin(), boxes.end(), [](const cv::Rect& a, const cv::Rect& b) { return a.area() > b.area(); });
  return boxes;
}

PhotoLandmarks FaceFinder::landmarks(const cv::Mat& gray, const cv::Rect& box) const {
  // Work on the face's neighbourhood only, enlarged when the face is small.
  const cv::Rect region = cv::Rect(box.x - box.width, box.y - box.height, 3 * box.width, 3 * box.height) &
                          cv::Rect(0, 0, gray.cols, gray.rows);
  const double scale = std::clamp(static_cast<double>(kLandmarkFaceWidth) / box.width, 1.0, kMaxUpscale);
  cv::Mat patch;
  if (scale > 1.0) cv::resize(gray(region), patch, cv::Size(), scale, scale, cv::INTER_CUBIC);
  else patch = gray(region);
  const auto to_patch = [&](int v, int origin) { return static_cast<long>((v - origin) * scale); };
  const dlib::rectangle face(to_patch(box.x, region.x), to_patch(box.y, region.y),
                             to_patch(box.x + box.width, region.x) - 1, to_patch(box.y + box.height, region.y) - 1);
  const dlib::full_object_detection shape = impl_->predictor(dlib::cv_image<unsigned char>(patch), face);
  PhotoLandmarks points{};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const dlib::point p = shape.part(static_cast<unsigned long>(i));
    // Pixel centres: patch pixel k covers photo pixels [k/scale, (k+1)/scale).
    points[i] = {static_cast<float>((static_cast<double>(p.x()) + 0.5) / scale - 0.5 + region.x),
                 static_cast<float>((static_cast<double>(p.y()) + 0.5) / scale - 0.5 + region.y)};
  }
  return points;
}

}  // namespace fw::photo
