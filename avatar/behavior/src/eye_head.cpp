#include "fw/behavior/eye_head.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "fw/behavior/gradient_noise.hpp"

namespace fw::behavior {
namespace {

constexpr float kDeg = 0.017453293f;
constexpr float kEyePitchRangeRad = 0.6f;

// Minimum-jerk profile: the bell-shaped velocity of a real saccade, peak
// speed 1.875 times the mean.
float minimum_jerk(double s) {
  const double c = std::clamp(s, 0.0, 1.0);
  return static_cast<float>(c * c * c * (10 - 15 * c + 6 * c * c));
}

YawPitch clamp_to_orbit(YawPitch e) {
  return {std::clamp(e.yaw_rad, -EyeHeadController::kOculomotorRangeRad, EyeHeadController::kOculomotorRangeRad),
          std::clamp(e.pitch_rad, -kEyePitchRangeRad, kEyePitchRangeRad)};
}

// How far the head goes for an error `e` (radians) on one axis.
float head_goal_offset(float e, float free_rad, float share) {
  const float beyond = std::max(0.0f, std::abs(e) - free_rad) * share;
  return e < 0 ? -beyond : beyond;
}

}  // namespace

double saccade_duration_s(float amplitude_rad) { return 0.021 + 0.0022 * std::abs(amplitude_rad) / kDeg; }

double head_movement_duration_s(float amplitude_rad) { return 0.15 + 0.005 * std::abs(amplitude_rad) / kDeg; }

EyeHeadController::EyeHeadController(const EyeHeadOptions& options)
    : options_(options), fixation_(options.seed ^ 0x5ACCADEull) {}

void EyeHeadController::look_at(glm::vec3 target_seat_mm) { target_ = target_seat_mm; }

HeadPose EyeHeadController::head() const {
  HeadPose pose = head_noise_;
  pose.yaw_rad += head_.yaw_rad;
  pose.pitch_rad += head_.pitch_rad;
  return pose;
}

YawPitch EyeHeadController::gaze() const {
  const HeadPose h = head();
  return {h.yaw_rad + eye_.yaw_rad, h.pitch_rad + eye_.pitch_rad};
}

glm::vec3 EyeHeadController::eye_position_seat() const { return head_to_seat(head(), head_geometry().eye_mid_mm); }

YawPitch EyeHeadController::target_direction() const { return direction_angles(target_ - eye_position_seat()); }

void EyeHeadController::start_saccade(YawPitch from, YawPitch target) {
  saccade_from_ = from;
  saccade_to_ = target;
  const float amplitude = std::hypot(target.yaw_rad - saccade_from_.yaw_rad, target.pitch_rad - saccade_from_.pitch_rad);
  saccade_duration_s_ = saccade_duration_s(amplitude);
  saccade_t_s_ = 0;
  saccade_active_ = true;
  saccade_started_rad_ = amplitude;
  // The head takes part of a large shift only; vertical shifts use it less.
  head_goal_.yaw_rad = head_.yaw_rad + head_goal_offset(target.yaw_rad - head_.yaw_rad, kHeadFreeRad, kHeadShare);
  head_goal_.pitch_rad = head_.pitch_rad + head_goal_offset(target.pitch_rad - head_.pitch_rad, 0.1f, 0.6f);
  head_goal_.yaw_rad = std::clamp(head_goal_.yaw_rad, -1.1f, 1.1f);
  head_goal_.pitch_rad = std::clamp(head_goal_.pitch_rad, -0.6f, 0.6f);
  // A new goal mid-movement starts a new movement from where the head is.
  head_from_ = head_;
  head_t_s_ = 0;
  head_duration_s_ = head_movement_duration_s(
      std::hypot(head_goal_.yaw_rad - head_.yaw_rad, head_goal_.pitch_rad - head_.pitch_rad));
}

void EyeHeadController::step(double dt_s) {
  time_s_ += dt_s;
  saccade_started_rad_ = 0;
  // Where the eyes point in space before the head moves this tick. Between
  // saccades the vestibulo-ocular reflex counter-rotates the eyes against the
  // head continuously, so this direction, not this tick's head plus last
  // tick's eyes, is the gaze to check against the target: the latter read
  // the head's own motion as an error and fired small corrective saccades
  // every other frame while the head finished a large shift.
  const YawPitch held = gaze();
  if (options_.head_noise) {
    const auto t = static_cast<float>(time_s_);
    const auto seed = static_cast<std::uint32_t>(options_.seed);
    head_noise_.yaw_rad = 2.5f * kDeg * gradient_noise(0.35f * t, seed);
    head_noise_.pitch_rad = 2.0f * kDeg * gradient_noise(0.3f * t, seed + 1);
    head_noise_.roll_rad = 1.5f * kDeg * gradient_noise(0.25f * t, seed + 2);
    head_noise_.translation_mm = {3.0f * gradient_noise(0.2f * t, seed + 3), 2.0f * gradient_noise(0.25f * t, seed + 4),
                                  3.0f * gradient_noise(0.15f * t, seed + 5)};
  }
  head_t_s_ += dt_s;
  const float s_head = head_duration_s_ > 0 ? minimum_jerk(head_t_s_ / head_duration_s_) : 1.0f;
  head_.yaw_rad = head_from_.yaw_rad + (head_goal_.yaw_rad - head_from_.yaw_rad) * s_head;
  head_.pitch_rad = head_from_.pitch_rad + (head_goal_.pitch_rad - head_from_.pitch_rad) * s_head;
  const HeadPose h = head();
  const YawPitch target = target_direction();

  if (saccade_active_) {
    saccade_t_s_ += dt_s;
    const float s = minimum_jerk(saccade_t_s_ / saccade_duration_s_);
    const YawPitch g{saccade_from_.yaw_rad + (saccade_to_.yaw_rad - saccade_from_.yaw_rad) * s,
                     saccade_from_.pitch_rad + (saccade_to_.pitch_rad - saccade_from_.pitch_rad) * s};
    eye_ = clamp_to_orbit({g.yaw_rad - h.yaw_rad, g.pitch_rad - h.pitch_rad});
    // A shift beyond the eyes' range ends when the head has carried gaze
    // the rest of the way, the eye waiting at its limit: one gaze shift,
    // not a saccade and then a corrective one (at most kHeadWaitS longer).
    const float left = std::hypot(saccade_to_.yaw_rad - h.yaw_rad - eye_.yaw_rad,
                                  saccade_to_.pitch_rad - h.pitch_rad - eye_.pitch_rad);
    if (saccade_t_s_ >= saccade_duration_s_ &&
        (left <= kSaccadeThresholdRad || saccade_t_s_ >= saccade_duration_s_ + kHeadWaitS)) {
      saccade_active_ = false;
      fixation_.reset();
    }
  } else {
    if (std::hypot(target.yaw_rad - held.yaw_rad, target.pitch_rad - held.pitch_rad) > kSaccadeThresholdRad) {
      start_saccade(held, target);
      saccade_t_s_ = dt_s;
      const float s = minimum_jerk(saccade_t_s_ / saccade_duration_s_);
      eye_ = clamp_to_orbit({saccade_from_.yaw_rad + (saccade_to_.yaw_rad - saccade_from_.yaw_rad) * s - h.yaw_rad,
                             saccade_from_.pitch_rad + (saccade_to_.pitch_rad - saccade_from_.pitch_rad) * s - h.pitch_rad});
    } else {
      // Vestibulo-ocular reflex: the eye counter-rotates against the head, so
      // gaze holds the target (plus the fixation micro-movements).
      const YawPitch fix = options_.micro_movements ? fixation_.step(dt_s) : YawPitch{};
      eye_ = clamp_to_orbit({target.yaw_rad + fix.yaw_rad - h.yaw_rad, target.pitch_rad + fix.pitch_rad - h.pitch_rad});
    }
  }
  // Vergence: both eyes turn in on near targets, slower than saccades.
  const float distance = std::max(50.0f, glm::length(target_ - eye_position_seat()));
  const float half_goal = std::atan(0.5f * head_geometry().interocular_mm / distance);
  half_vergence_rad_ += (half_goal - half_vergence_rad_) * static_cast<float>(1 - std::exp(-dt_s / kVergenceTimeConstantS));
}

void EyeHeadController::write(codec::FaceParams& params) const {
  const HeadPose h = head();
  params.head_yaw_rad = h.yaw_rad;
  params.head_pitch_rad = h.pitch_rad;
  params.head_roll_rad = h.roll_rad;
  params.head_translation_mm = {h.translation_mm.x, h.translation_mm.y, h.translation_mm.z};
  // The person's left eye sits toward +x: it turns toward its right (negative
  // yaw) to converge.
  params.eye_left = {eye_.yaw_rad - half_vergence_rad_, eye_.pitch_rad};
  params.eye_right = {eye_.yaw_rad + half_vergence_rad_, eye_.pitch_rad};
}

}  // namespace fw::behavior
