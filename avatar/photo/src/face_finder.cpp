#include "face_finder.hpp"

#include <algorithm>

#include <cmath>

#include <dlib/image_processing.h>
#include <glm/geometric.hpp>
#include <dlib/image_processing/frontal_face_detector.h>
#include <dlib/opencv.h>
#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

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
// Detections below this confidence are mostly not faces (badges, patterns);
// the best one is kept all the same when nothing scores higher.
constexpr double kMinConfidence = 0.2;
// A face found this confidently in the photo as it is needs no other view.
constexpr double kConfidentFace = 0.5;
// Where dlib's detector puts its box relative to the eyes on upright frontal
// faces (measured): 2.05 inter-ocular distances wide, centred 0.52 of them
// below the eye midpoint. The second landmark pass uses this box, so the
// landmarks no longer depend on how the detector happened to frame the face.
constexpr double kBoxWidthIod = 2.05;
constexpr double kBoxCentreBelowEyesIod = 0.52;
// The second pass sees the face upright at its full resolution, enlarged to
// at least kMinUprightIodPx between the eyes when smaller (landmarks are
// whole pixels), and reduced to kMaxUprightIodPx when larger (more detail
// does not help the predictor, and the patch grows with its square).
constexpr double kMinUprightIodPx = 100.0, kMaxUprightIodPx = 400.0;

}  // namespace

// The fallback cascade must see a face this many times over (at nearby
// places and scales) before it counts: a real face gathers 10 to 30, a
// mouth or a pattern a handful.
constexpr int kFallbackMinNeighbours = 8;
// Its box against dlib's on the same faces (measured on the test photos and
// renders of their avatars: dlib's is 0.78 to 1.05 times as wide, centred
// 0.05 to 0.125 of the width lower): a little larger, higher up the forehead.
constexpr double kFallbackBoxScale = 0.9, kFallbackBoxShiftDown = 0.1;

struct FaceFinder::Impl {
  dlib::frontal_face_detector detector = dlib::get_frontal_face_detector();
  dlib::shape_predictor predictor;
  cv::CascadeClassifier fallback;
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
  if (!finder->impl_->fallback.load(kFallbackFaceCascade)) {
    error = {PrepErrorCode::model_missing, std::string("the face cascade is not at ") + kFallbackFaceCascade +
                                               " (install Debian's opencv-data)"};
    return nullptr;
  }
  return finder;
}

namespace {

// The photo turned by `degrees` (counterclockwise) about its centre, on a
// canvas large enough to hold all of it.
cv::Matx23d turn_whole(cv::Size size, double degrees, cv::Size& turned_size) {
  const cv::Point2f centre(static_cast<float>(size.width) / 2.0f, static_cast<float>(size.height) / 2.0f);
  cv::Matx23d m = cv::getRotationMatrix2D(centre, degrees, 1.0);
  const double c = std::abs(m(0, 0)), s = std::abs(m(0, 1));
  turned_size = cv::Size(static_cast<int>(std::lround(size.width * c + size.height * s)),
                         static_cast<int>(std::lround(size.width * s + size.height * c)));
  m(0, 2) += turned_size.width / 2.0 - centre.x;
  m(1, 2) += turned_size.height / 2.0 - centre.y;
  return m;
}

// The bounding box, in photo pixels, of `box` in a view `photo_to_view`.
cv::Rect box_in_photo(const cv::Rect& box, const cv::Matx23d& photo_to_view) {
  cv::Matx23d view_to_photo;
  cv::invertAffineTransform(photo_to_view, view_to_photo);
  std::vector<cv::Point2f> corners;
  for (const cv::Point2f c : {cv::Point2f(box.tl()), cv::Point2f(box.br()), cv::Point2f(box.x, box.y + box.height),
                              cv::Point2f(box.x + box.width, box.y)}) {
    const cv::Vec3d q(c.x, c.y, 1.0);
    const cv::Vec2d p = view_to_photo * q;
    corners.emplace_back(static_cast<float>(p[0]), static_cast<float>(p[1]));
  }
  return cv::boundingRect(corners);
}

}  // namespace

std::vector<FoundFace> FaceFinder::detect(const cv::Mat& gray) {
  // The photo as it is first. A confident face there ends the search; a
  // weak one (a face rolled far over is often half seen) or none sends the
  // detector to the turned views, and the view with the most confident face
  // wins.
  std::vector<FoundFace> best;
  double best_confidence = -1e9;
  for (const double turn : {0.0, 90.0, -90.0, 180.0, 45.0, -45.0, 135.0, -135.0}) {
    cv::Matx23d photo_to_view(1, 0, 0, 0, 1, 0);
    cv::Mat turned;  // its own pixels: warping into `gray`'s would overwrite the photo
    if (turn != 0.0) {
      cv::Size size;
      photo_to_view = turn_whole(gray.size(), turn, size);
      cv::warpAffine(gray, turned, photo_to_view, size, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    }
    double confidence = 0;
    const std::vector<cv::Rect> boxes = detect_in(turn == 0.0 ? gray : turned, confidence);
    if (boxes.empty() || confidence <= best_confidence) continue;
    best.clear();
    best_confidence = confidence;
    for (const cv::Rect& box : boxes)
      best.push_back({turn == 0.0 ? box : box_in_photo(box, photo_to_view), photo_to_view, box, turn});
    if (confidence >= kConfidentFace) break;
  }
  // Turned views must be confident: a view the photo does not need should
  // not find a face in a pattern.
  if (!best.empty() && best.front().turn_deg != 0.0 && best_confidence < kMinConfidence) best.clear();
  if (best.empty())
    for (const cv::Rect& box : detect_with_fallback(gray)) best.push_back({box, {1, 0, 0, 0, 1, 0}, box, 0.0, true});
  return best;
}

std::vector<cv::Rect> FaceFinder::detect_with_fallback(const cv::Mat& gray) {
  // dlib's HOG detector was trained on faces within about 25 degrees of
  // level; OpenCV's cascade still finds a head tilted further back. The
  // shape predictor then needs a box framed as dlib frames one.
  const double scale = std::min(kMaxUpscale, static_cast<double>(kDetectionSide) / std::max(gray.cols, gray.rows));
  cv::Mat small;
  cv::resize(gray, small, cv::Size(), scale, scale, scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  std::vector<cv::Rect> found;
  impl_->fallback.detectMultiScale(small, found, 1.1, kFallbackMinNeighbours, 0, cv::Size(40, 40));
  std::vector<cv::Rect> boxes;
  for (const cv::Rect& r : found) {
    const double side = r.width * kFallbackBoxScale / scale;
    const double cx = (r.x + 0.5 * r.width) / scale;
    const double cy = (r.y + (0.5 + kFallbackBoxShiftDown) * r.height) / scale;
    boxes.emplace_back(static_cast<int>(std::lround(cx - 0.5 * side)), static_cast<int>(std::lround(cy - 0.5 * side)),
                       static_cast<int>(std::lround(side)), static_cast<int>(std::lround(side)));
  }
  std::sort(boxes.begin(), boxes.end(), [](const cv::Rect& a, const cv::Rect& b) { return a.area() > b.area(); });
  return boxes;
}

std::vector<cv::Rect> FaceFinder::detect_in(const cv::Mat& gray, double& best_confidence) {
  std::vector<cv::Rect> boxes;
  for (const int side : {kDetectionSide, 2 * kDetectionSide}) {
    const double scale = std::min(kMaxUpscale, static_cast<double>(side) / std::max(gray.cols, gray.rows));
    if (side > kDetectionSide && scale >= 1.0) break;  // the first look already saw it at full size
    cv::Mat small;
    if (scale < 1.0) cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_AREA);
    else if (scale > 1.0) cv::resize(gray, small, cv::Size(), scale, scale, cv::INTER_LINEAR);
    else small = gray;
    const dlib::cv_image<unsigned char> image(small);
    std::vector<dlib::rect_detection> detections;
    impl_->detector(image, detections);
    if (detections.empty()) continue;
    std::sort(detections.begin(), detections.end(),
              [](const auto& a, const auto& b) { return a.detection_confidence > b.detection_confidence; });
    best_confidence = detections.front().detection_confidence;
    for (std::size_t i = 0; i < detections.size(); ++i) {
      if (i > 0 && detections[i].detection_confidence < kMinConfidence) break;
      const dlib::rectangle& r = detections[i].rect;
      boxes.emplace_back(static_cast<int>(r.left() / scale), static_cast<int>(r.top() / scale),
                         static_cast<int>(r.width() / scale), static_cast<int>(r.height() / scale));
    }
    break;
  }
  std::sort(boxes.begin(), boxes.end(), [](const cv::Rect& a, const cv::Rect& b) { return a.area() > b.area(); });
  return boxes;
}

// Runs the shape predictor on `gray` warped by `photo_to_patch` (2x3) into a
// patch of `size`, with the face box given in patch pixels; landmarks come
// back in photo pixels.
PhotoLandmarks FaceFinder::predict(const cv::Mat& gray, const cv::Matx23d& photo_to_patch, cv::Size size,
                                   const cv::Rect2d& box) const {
  cv::Mat patch;
  cv::warpAffine(gray, patch, photo_to_patch, size, cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  const dlib::rectangle face(std::lround(box.x), std::lround(box.y), std::lround(box.x + box.width) - 1,
                             std::lround(box.y + box.height) - 1);
  const dlib::full_object_detection shape = impl_->predictor(dlib::cv_image<unsigned char>(patch), face);
  cv::Matx23d patch_to_photo;
  cv::invertAffineTransform(photo_to_patch, patch_to_photo);
  PhotoLandmarks points{};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const dlib::point p = shape.part(static_cast<unsigned long>(i));
    const cv::Vec3d q(static_cast<double>(p.x()), static_cast<double>(p.y()), 1.0);
    const cv::Vec2d photo = patch_to_photo * q;
    points[i] = {static_cast<float>(photo[0]), static_cast<float>(photo[1])};
  }
  return points;
}

PhotoLandmarks FaceFinder::landmarks(const cv::Mat& gray, const FoundFace& face) const {
  // Pass 1: the detector's box, on the face's neighbourhood in the
  // detector's view, enlarged when the face is small (the predictor's
  // landmarks are whole patch pixels).
  const cv::Rect& box = face.view_box;
  const double scale = std::clamp(static_cast<double>(kLandmarkFaceWidth) / box.width, 1.0, kMaxUpscale);
  const cv::Point2d origin(box.x - box.width, box.y - box.height);
  const cv::Matx33d view_to_patch(scale, 0, -origin.x * scale, 0, scale, -origin.y * scale, 0, 0, 1);
  const cv::Matx33d photo_to_view(face.photo_to_view(0, 0), face.photo_to_view(0, 1), face.photo_to_view(0, 2),
                                  face.photo_to_view(1, 0), face.photo_to_view(1, 1), face.photo_to_view(1, 2), 0, 0, 1);
  const cv::Matx33d photo_to_patch = view_to_patch * photo_to_view;
  const cv::Matx23d crop(photo_to_patch(0, 0), photo_to_patch(0, 1), photo_to_patch(0, 2), photo_to_patch(1, 0),
                         photo_to_patch(1, 1), photo_to_patch(1, 2));
  const cv::Size crop_size(static_cast<int>(3 * box.width * scale), static_cast<int>(3 * box.height * scale));
  const PhotoLandmarks first =
      predict(gray, crop, crop_size, cv::Rect2d(box.width * scale, box.height * scale, box.width * scale, box.height * scale));

  // Pass 2: the face turned upright at a fixed size, with the box placed
  // from the eyes, so rotation, scale and framing of the photo matter less.
  glm::vec2 right(0.0f), left(0.0f);
  for (int i = 0; i < 6; ++i) right += first[static_cast<std::size_t>(36 + i)] / 6.0f, left += first[static_cast<std::size_t>(42 + i)] / 6.0f;
  const glm::vec2 eyes = 0.5f * (left + right);
  const double iod = std::max(1.0, static_cast<double>(glm::length(left - right)));
  const double angle = std::atan2(static_cast<double>(left.y - right.y), static_cast<double>(left.x - right.x));
  const double upright_iod = std::clamp(iod, kMinUprightIodPx, kMaxUprightIodPx);
  const double s = upright_iod / iod, c = std::cos(-angle) * s, n = std::sin(-angle) * s;
  const cv::Size size(static_cast<int>(4 * upright_iod), static_cast<int>(4 * upright_iod));
  const cv::Point2d centre(size.width / 2.0, size.height * 0.4);  // eyes a little above the middle
  const cv::Matx23d upright(c, -n, centre.x - (c * eyes.x - n * eyes.y), n, c, centre.y - (n * eyes.x + c * eyes.y));
  const double width = kBoxWidthIod * upright_iod;
  const cv::Rect2d canonical(centre.x - width / 2, centre.y + kBoxCentreBelowEyesIod * upright_iod - width / 2, width, width);
  return predict(gray, upright, size, canonical);
}

}  // namespace fw::photo
