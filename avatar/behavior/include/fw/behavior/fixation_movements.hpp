#pragma once
// The eyes' micro-movements while fixating ("Behavioral Animation of Faces",
// section 5): slow drift, rapid small tremor, and micro-saccades that bring
// the eye back when the drift has carried it too far off target.
#include <cstdint>
#include <random>

#include "fw/behavior/seat_layout.hpp"

namespace fw::behavior {

class FixationMovements {
 public:
  static constexpr float kDriftRadPerS = 0.0035f;    ///< about 0.2 deg/s of slow drift
  static constexpr float kTremorRad = 0.0003f;       ///< tremor amplitude (a minute of arc)
  static constexpr float kMicrosaccadeAtRad = 0.007f;  ///< drift that triggers a micro-saccade (0.4 deg)

  explicit FixationMovements(std::uint64_t seed);
  /// Advances `dt_s`; the offset of gaze from the target it fixates.
  YawPitch step(double dt_s);
  /// A (macro) saccade lands: fixation starts afresh on the new target.
  void reset();
  int microsaccades() const { return microsaccades_; }

 private:
  std::mt19937_64 rng_;
  YawPitch drift_{};
  YawPitch drift_velocity_{};
  int microsaccades_ = 0;
};

}  // namespace fw::behavior
