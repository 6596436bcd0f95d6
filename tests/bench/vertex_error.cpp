#include "vertex_error.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "fw/model/face_reconstruction.hpp"
#include "fw/render/camera.hpp"

namespace fw::bench {
namespace {

// The skin of `params` in millimetres, posed as the renderer poses a head.
std::vector<glm::vec3> posed_skin_mm(const model::AvatarModel& avatar, const codec::FaceParams& params) {
  model::FaceShape shape = model::reconstruct_face(avatar, params);
  render::HeadPose pose;
  pose.yaw_rad = params.head_yaw_rad;
  pose.pitch_rad = params.head_pitch_rad;
  pose.roll_rad = params.head_roll_rad;
  pose.translation = glm::vec3(params.head_translation_mm[0], params.head_translation_mm[1],
                               params.head_translation_mm[2]) /
                     static_cast<float>(kInterOcularMm);
  const glm::mat4 transform = render::head_transform(pose);
  for (glm::vec3& p : shape.positions)
    p = glm::vec3(transform * glm::vec4(p, 1.0f)) * static_cast<float>(kInterOcularMm);
  return std::move(shape.positions);
}

}  // namespace

void VertexError::add(const codec::FaceParams& original, const codec::FaceParams& shown) {
  const std::vector<glm::vec3> a = posed_skin_mm(avatar_, original);
  const std::vector<glm::vec3> b = posed_skin_mm(avatar_, shown);
  for (std::size_t v = 0; v < a.size(); ++v) {
    const double d = glm::distance(a[v], b[v]);
    sum_sq_mm_ += d * d;
    max_mm_ = std::max(max_mm_, d);
  }
  samples_ += a.size();
}

double VertexError::rms_mm() const { return samples_ ? std::sqrt(sum_sq_mm_ / static_cast<double>(samples_)) : 0.0; }

}  // namespace fw::bench
