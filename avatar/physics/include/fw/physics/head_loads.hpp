#pragma once
// What a tilting, turning head does to its soft tissue. The tissue is
// simulated in the head's own frame, where the skull holds still, so a head
// that leaves upright or accelerates puts an acceleration field on every
// node (Kozlov et al. 2017, "Enriching facial blendshape rigs with physical
// simulation", add this secondary motion to a rig the same way):
//
//   a(p) = R^T g - g                      the part of gravity that the
//                                         upright rest shape does not balance
//        - R^T a_pivot                    the neck pivot's own acceleration
//        - alpha x r - omega x (omega x r)  the turn's (r = p - the pivot)
//
// R is the head's rotation (the renderer's: yaw, then pitch, then roll about
// model::kNeckPivot), omega and alpha its angular velocity and acceleration
// in the head's frame. The Coriolis term (2 omega x v) is left out: the
// tissue moves at mm/s against a head that turns at a few rad/s, under 1 %
// of the rest. The field is the sum of a uniform part and a part linear in
// r, so applying it costs a 3 x 3 product per node.
#include <algorithm>
#include <cstddef>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "fw/model/head_pose.hpp"
#include "fw/model/landmark_template.hpp"

namespace fw::physics {

/// Standard gravity in model units per s^2 (9.81 m/s^2).
inline constexpr float kGravityUnits = 9810.0f / model::kMillimetresPerUnit;
/// A head turning faster than this, or its pivot moving faster than
/// kMaxPivotSpeedMmS, has been put somewhere, not moved there: the frame is
/// a cut and starts the motion afresh. Voluntary head turns peak near 5
/// rad/s (about 300 deg/s in large gaze shifts, Freedman & Sparks 1997).
inline constexpr float kMaxHeadSpeedRadS = 10.0f;
inline constexpr float kMaxPivotSpeedMmS = 2000.0f;

using model::HeadPose;

/// An acceleration field in the head's frame: uniform + linear (p - pivot),
/// model units per s^2.
struct HeadLoad {
  glm::vec3 uniform{0.0f};
  glm::mat3 linear{0.0f};
  glm::vec3 at(const glm::vec3& p) const { return uniform + linear * (p - model::kNeckPivot); }
  bool none() const { return *this == HeadLoad{}; }
  bool operator==(const HeadLoad&) const = default;
};

/// Follows a head's pose frame by frame (finite differences) and gives the
/// load on its tissue over each frame.
class HeadMotion {
 public:
  /// The pose the head reaches at the end of the next frame.
  void set_pose(const HeadPose& pose) { next_ = pose; }
  const HeadPose& pose() const { return next_; }
  /// Moves on by a frame of `dt_s` ending at the pose set last and returns
  /// the load over it, times `scale` (TissueMaterial::load_scale). A
  /// non-finite or non-positive dt returns the last load unchanged.
  HeadLoad advance(double dt_s, float scale);

 private:
  HeadPose next_{};
  bool started_ = false;
  glm::mat3 rotation_{1.0f};
  glm::vec3 pivot_mm_{0.0f}, pivot_speed_mm_s_{0.0f}, omega_{0.0f};
  HeadLoad load_{};
};

/// Kernel: the force `load` puts on each of `count` nodes of mass `mass` at
/// (x, y, z), written into (fx, fy, fz) (not added: the solvers start their
/// force sums with it).
inline void fill_load_forces(const HeadLoad& load, float mass, std::size_t count, const float* x, const float* y,
                             const float* z, float* fx, float* fy, float* fz) {
  const glm::vec3 u = mass * (load.uniform - load.linear * model::kNeckPivot);
  const glm::mat3 l = mass * load.linear;
  if (l == glm::mat3(0.0f)) {
    std::fill(fx, fx + count, u.x), std::fill(fy, fy + count, u.y), std::fill(fz, fz + count, u.z);
    return;
  }
  for (std::size_t i = 0; i < count; ++i) {
    fx[i] = u.x + l[0][0] * x[i] + l[1][0] * y[i] + l[2][0] * z[i];
    fy[i] = u.y + l[0][1] * x[i] + l[1][1] * y[i] + l[2][1] * z[i];
    fz[i] = u.z + l[0][2] * x[i] + l[1][2] * y[i] + l[2][2] * z[i];
  }
}

}  // namespace fw::physics
