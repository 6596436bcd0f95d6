#include "fw/behavior/fixation_movements.hpp"

#include <cmath>

namespace fw::behavior {

FixationMovements::FixationMovements(std::uint64_t seed) : rng_(seed) {}

void FixationMovements::reset() { drift_ = {}; }

YawPitch FixationMovements::step(double dt_s) {
  std::normal_distribution<float> normal(0.0f, 1.0f);
  // Drift: a velocity that wanders (Ornstein-Uhlenbeck), so the eye slides
  // slowly instead of jittering.
  const float k = static_cast<float>(std::min(1.0, dt_s / 0.5));
  const float kick = kDriftRadPerS * std::sqrt(2.0f * k);
  drift_velocity_.yaw_rad += -drift_velocity_.yaw_rad * k + kick * normal(rng_);
  drift_velocity_.pitch_rad += -drift_velocity_.pitch_rad * k + kick * normal(rng_);
  drift_.yaw_rad += drift_velocity_.yaw_rad * static_cast<float>(dt_s);
  drift_.pitch_rad += drift_velocity_.pitch_rad * static_cast<float>(dt_s);
  if (std::hypot(drift_.yaw_rad, drift_.pitch_rad) > kMicrosaccadeAtRad) {
    // A micro-saccade lasts ~20 ms, under one tick: it lands within a tick.
    drift_.yaw_rad *= 0.1f;
    drift_.pitch_rad *= 0.1f;
    ++microsaccades_;
  }
  return {drift_.yaw_rad + kTremorRad * normal(rng_), drift_.pitch_rad + kTremorRad * normal(rng_)};
}

}  // namespace fw::behavior
