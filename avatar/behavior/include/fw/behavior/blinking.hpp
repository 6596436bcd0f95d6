#pragma once
// Spontaneous blinks (about 10-20 a minute at rest), blinks that go with
// large gaze shifts, and lids that follow the eyes' pitch (the upper lid
// drops when the eyes look down).
#include <cstdint>
#include <random>

namespace fw::behavior {

class Blinking {
 public:
  static constexpr double kRestRatePerMin = 15.0;   ///< spontaneous rate
  static constexpr double kRefractoryS = 0.8;       ///< no blink sooner than this after one
  static constexpr float kGazeBlinkFromRad = 0.44f; ///< shifts larger than ~25 degrees may blink
  static constexpr double kCloseS = 0.08, kClosedS = 0.04, kOpenS = 0.16;

  explicit Blinking(std::uint64_t seed);
  /// Advances `dt_s`; `saccade_started_rad` is the amplitude of a saccade that
  /// started this step (0 if none).
  void step(double dt_s, float saccade_started_rad);
  /// Lid closure of the blink now, 0 .. 1.
  float closure() const;
  /// Whether a blink started in the last step.
  bool started() const { return started_; }
  int count() const { return count_; }

 private:
  void start();
  double next_interval();

  std::mt19937_64 rng_;
  double since_last_s_ = 1e9;
  double until_next_s_;
  double blink_t_s_ = -1;  ///< time into the current blink, < 0: none
  bool started_ = false;
  int count_ = 0;
};

/// How far the upper lids close because the eyes look down (`eye_pitch_rad`
/// negative), 0 .. 0.45.
float lid_follows_pitch(float eye_pitch_rad);

}  // namespace fw::behavior
