#include "head_pose_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <opencv2/core.hpp>

#include "face_alignment.hpp"
#include "fw/model/depth_profile.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

constexpr float kDegreesPerRadian = 57.29578f;
// The pose comes from the inner face (brows, nose, eyes, mouth): points of
// the skin at every angle. dlib puts the jaw line on the outline, which
// slides over the cheek as the head turns.
bool on_jaw_line(std::size_t i) { return static_cast<int>(i) < lm::kJawEnd; }
// The face's height needs evidence to move from the generic one.
constexpr double kHeightPull = 0.02;
constexpr float kMostHeight = 0.25f;
constexpr int kIterations = 10;
// A residual is laid back onto the surface only this far (model units):
// where the surface turns edge-on, a small error in the image would be a
// large one on the face.
constexpr float kLongestStep = 0.25f;
// From this turn on, the jaw line is the outline, not the jaw: its points
// keep only their height, and the generic face's width.
constexpr float kOutlineFromDeg = 20.0f;

// The nearest scaled rotation to an affine camera's 2x3 part.
void to_scaled_rotation(const cv::Matx23d& affine, glm::mat3& rotation, float& scale) {
  cv::Mat w, u, vt;
  cv::SVD::compute(cv::Mat(affine), w, u, vt);
  const cv::Mat rows = u * vt.rowRange(0, 2);  // 2x3, orthonormal rows
  const glm::vec3 r1(rows.at<double>(0, 0), rows.at<double>(0, 1), rows.at<double>(0, 2));
  const glm::vec3 r2(rows.at<double>(1, 0), rows.at<double>(1, 1), rows.at<double>(1, 2));
  scale = static_cast<float>(0.5 * (w.at<double>(0) + w.at<double>(1)));
  // glm is column-major: the rows r1, r2, r1 x r2.
  rotation = glm::transpose(glm::mat3(r1, r2, glm::cross(r1, r2)));
}

// The person's face in the fit's frame: the generic relief under a face
// stretched along y by `height` (the eyes, at y = 0, stay).
glm::vec3 stretched_point(glm::vec2 p, float height) {
  return {p.x, p.y, model::face_depth({p.x, p.y / (1.0f + height)})};
}

void fit_camera(const std::array<glm::vec3, model::kLandmarkCount>& points, const ModelLandmarks& aligned,
                HeadPose& pose) {
  glm::dvec3 mean_p(0.0);
  glm::dvec2 mean_q(0.0);
  double count = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (on_jaw_line(i)) continue;
    mean_p += glm::dvec3(points[i]);
    mean_q += glm::dvec2(aligned[i]);
    ++count;
  }
  mean_p /= count, mean_q /= count;
  cv::Matx33d pp = cv::Matx33d::zeros();
  cv::Matx23d qp = cv::Matx23d::zeros();
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (on_jaw_line(i)) continue;
    const glm::dvec3 p = glm::dvec3(points[i]) - mean_p;
    const glm::dvec2 q = glm::dvec2(aligned[i]) - mean_q;
    const cv::Vec3d pv(p.x, p.y, p.z);
    pp += pv * pv.t();
    qp += cv::Vec2d(q.x, q.y) * pv.t();
  }
  to_scaled_rotation(qp * pp.inv(cv::DECOMP_SVD), pose.rotation, pose.scale);
  pose.shift = glm::vec2(0.0f);  // project() adds the shift: measure without it
  pose.shift = glm::vec2(mean_q) - pose.project(glm::vec3(mean_p));
}

float fit_height(const std::array<glm::vec3, model::kLandmarkCount>& generic_points, const ModelLandmarks& aligned,
                 const HeadPose& pose) {
  double normal = kHeightPull, rhs = 0;
  for (std::size_t i = 0; i < generic_points.size(); ++i) {
    if (on_jaw_line(i)) continue;
    const glm::vec2 along = pose.scale * glm::vec2(pose.rotation * glm::vec3(0, generic_points[i].y, 0));
    const glm::vec2 r = aligned[i] - pose.project(generic_points[i]);
    normal += glm::dot(along, along);
    rhs += glm::dot(along, r);
  }
  return std::clamp(static_cast<float>(rhs / normal), -kMostHeight, kMostHeight);
}

}  // namespace

glm::vec2 HeadPose::project(glm::vec3 p) const { return scale * glm::vec2(rotation * p) + shift; }

float HeadPose::facing(glm::vec3 n) const { return (rotation * n).z; }

glm::vec2 PoseFit::to_fit_frame(glm::vec2 p) const { return frontal_to_fit * (p - frontal_origin); }

glm::vec3 PoseFit::surface(glm::vec2 frontal_point) const {
  return stretched_point(to_fit_frame(frontal_point), pose.height_mode);
}

PoseFit fit_head_pose(const model::GenericFace& generic, const ModelLandmarks& aligned) {
  PoseFit fit;
  HeadPose& pose = fit.pose;
  const std::size_t n = aligned.size();
  std::array<glm::vec3, model::kLandmarkCount> anchors{}, points{};
  for (std::size_t i = 0; i < n; ++i) anchors[i] = generic.skin.positions[generic.landmark_vertices[i]];
  // Camera and shape in turn: each is a linear problem given the other.
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    for (std::size_t i = 0; i < n; ++i)
      points[i] = stretched_point({anchors[i].x, anchors[i].y * (1.0f + pose.height_mode)}, pose.height_mode);
    fit_camera(points, aligned, pose);
    pose.height_mode = fit_height(anchors, aligned, pose);
  }
  const glm::vec3 nose = pose.rotation * glm::vec3(0, 0, 1), across = pose.rotation * glm::vec3(1, 0, 0);
  pose.yaw_deg = std::atan2(nose.x, nose.z) * kDegreesPerRadian;
  pose.pitch_deg = std::asin(std::clamp(nose.y, -1.0f, 1.0f)) * kDegreesPerRadian;
  pose.roll_deg = std::atan2(across.y, across.x) * kDegreesPerRadian;

  // What the camera and the shape leave is the person's own shape: each
  // landmark's image-plane residual, laid back onto the surface there.
  ModelLandmarks frontal{};
  const float outline = std::clamp(std::abs(pose.yaw_deg) / kOutlineFromDeg, 0.0f, 1.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::vec2 p(anchors[i].x, anchors[i].y * (1.0f + pose.height_mode));
    constexpr float h = 0.01f;
    const glm::vec3 at = stretched_point(p, pose.height_mode);
    const glm::vec3 tx = (stretched_point(p + glm::vec2(h, 0), pose.height_mode) - at) / h;
    const glm::vec3 ty = (stretched_point(p + glm::vec2(0, h), pose.height_mode) - at) / h;
    const glm::mat2 jacobian(pose.scale * glm::vec2(pose.rotation * tx), pose.scale * glm::vec2(pose.rotation * ty));
    glm::vec2 step(0.0f);
    if (std::abs(glm::determinant(jacobian)) > 0.1f * pose.scale * pose.scale)
      step = glm::inverse(jacobian) * (aligned[i] - pose.project(at));
    if (on_jaw_line(i)) step.x *= 1.0f - outline;
    if (glm::length(step) > kLongestStep) step *= kLongestStep / glm::length(step);
    frontal[i] = p + step;
  }
  // The model frame puts the frontal eye centres at (+-0.5, 0).
  const glm::vec2 right = landmark_centre(frontal, lm::kEyeRightBegin, lm::kEyeRightEnd);
  const glm::vec2 left = landmark_centre(frontal, lm::kEyeLeftBegin, lm::kEyeLeftEnd);
  const float length = std::max(1e-3f, glm::length(left - right));
  const glm::vec2 c = (left - right) / length;
  // Rotate by the eye line's angle back to level, and scale to one unit.
  const glm::mat2 to_frontal = glm::mat2(glm::vec2(c.x, -c.y), glm::vec2(c.y, c.x)) / length;
  const glm::vec2 midpoint = 0.5f * (left + right);
  for (std::size_t i = 0; i < n; ++i) fit.frontal[i] = to_frontal * (frontal[i] - midpoint);
  fit.frontal_to_fit = glm::inverse(to_frontal);
  fit.frontal_origin = -(to_frontal * midpoint);
  return fit;
}

}  // namespace fw::photo
