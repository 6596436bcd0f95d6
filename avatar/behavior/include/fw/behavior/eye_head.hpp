#pragma once
// Eye-head coordination ("Behavioral Animation of Faces", section 5 and its
// Figure 8). A gaze shift is a saccade whose duration and peak speed grow with
// its amplitude (the main sequence); the head, far heavier, moves more slowly,
// with the bell-shaped velocity of a minimum-jerk movement lasting a few
// hundred milliseconds (head_movement_duration_s), and carries part of a
// large shift; once gaze is on the
// target the vestibulo-ocular reflex counter-rotates the eyes so gaze stays
// put while the head finishes. Both eyes converge on near targets, fixation
// drifts and trembles, and low-level Perlin noise keeps the head from
// freezing.
#include <cstdint>

#include <glm/vec3.hpp>

#include "fw/behavior/fixation_movements.hpp"
#include "fw/behavior/seat_layout.hpp"
#include "fw/codec/face_params.hpp"

namespace fw::behavior {

struct EyeHeadOptions {
  std::uint64_t seed = 1;
  bool micro_movements = true;  ///< drift, tremor, micro-saccades
  bool head_noise = true;       ///< Perlin noise on the head angles
};

/// The main sequence of saccades: duration in seconds of a saccade of
/// `amplitude_rad` (Carpenter: about 21 ms + 2.2 ms per degree).
double saccade_duration_s(float amplitude_rad);

/// How long the head takes to turn `amplitude_rad`: 150 ms plus 5 ms per
/// degree, so a 45-degree turn lasts about 0.4 s. Head movements
/// in gaze shifts last several hundred milliseconds, growing with their
/// size, with a single-peaked (bell-shaped) velocity (Zangemeister & Stark
/// 1982, "Types of gaze movement", Exp. Neurology 77; Freedman 2008,
/// "Coordination of the eyes and head during visual orienting", Exp. Brain
/// Research 190).
double head_movement_duration_s(float amplitude_rad);

class EyeHeadController {
 public:
  static constexpr float kOculomotorRangeRad = 0.8f;   ///< eye in orbit, ~46 degrees
  static constexpr float kSaccadeThresholdRad = 0.026f;  ///< smaller errors are left to fixation (1.5 deg)
  static constexpr float kHeadFreeRad = 0.14f;          ///< the eyes alone take the first 8 degrees
  static constexpr float kHeadShare = 0.9f;             ///< of the rest, the head's final share
  static constexpr double kVergenceTimeConstantS = 0.15;
  /// The longest a gaze shift beyond the eyes' range waits for the head.
  static constexpr double kHeadWaitS = 0.4;

  explicit EyeHeadController(const EyeHeadOptions& options);

  /// The point to look at, in the seat frame (millimetres).
  void look_at(glm::vec3 target_seat_mm);
  /// Advances `dt_s`.
  void step(double dt_s);

  /// Gaze (head + eye) of the cyclopean eye, seat frame.
  YawPitch gaze() const;
  /// Where the target lies from the eyes now.
  YawPitch target_direction() const;
  HeadPose head() const;
  /// The cyclopean eye in its orbit (vergence not included).
  YawPitch eye() const { return eye_; }
  bool in_saccade() const { return saccade_active_; }
  /// Amplitude of the saccade that started in the last step, else 0.
  float saccade_started_rad() const { return saccade_started_rad_; }
  /// The cyclopean eye's position in the seat frame.
  glm::vec3 eye_position_seat() const;

  /// Head rotation and translation, both eyes (with vergence) into `params`.
  void write(codec::FaceParams& params) const;

 private:
  void start_saccade(YawPitch from, YawPitch target);

  EyeHeadOptions options_;
  FixationMovements fixation_;
  glm::vec3 target_{0.0f, 0.0f, 1000.0f};
  double time_s_ = 0;
  // Head: kinematic part moving from `head_from_` to its goal along a
  // minimum-jerk profile, plus noise.
  YawPitch head_{}, head_from_{}, head_goal_{};
  double head_t_s_ = 0, head_duration_s_ = 0;
  HeadPose head_noise_{};
  // Eye in orbit, cyclopean.
  YawPitch eye_{};
  YawPitch fixation_offset_{};
  float half_vergence_rad_ = 0;
  // The saccade in flight: gaze from `from` to `to` over `duration`.
  bool saccade_active_ = false;
  YawPitch saccade_from_{}, saccade_to_{};
  double saccade_t_s_ = 0, saccade_duration_s_ = 0;
  float saccade_started_rad_ = 0;
};

}  // namespace fw::behavior
