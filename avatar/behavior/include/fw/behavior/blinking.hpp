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
  /// A blink's whole duration varies from blink to blink within the human
  /// range of 100-400 ms (Schiffman, "Sensation and Perception", 2001),
  /// around about 200 ms for an alert person (Caffier, Erdmann & Ullsperger
  /// 2003, "Experimental evaluation of eye-blink parameters as a drowsiness
  /// measure": ~200 ms alert, longer when drowsy): drawn log-normally.
  static constexpr double kMedianBlinkS = 0.2, kBlinkSpread = 0.3;  ///< median, sigma of log(duration)
  static constexpr double kShortestBlinkS = 0.1, kLongestBlinkS = 0.4;
  /// The lid rests closed this long (at least one 30 Hz tick sees it shut);
  /// of the rest, closing takes about a third and reopening two thirds (the
  /// lid falls fast and rises slowly; Caffier et al. 2003).
  static constexpr double kClosedS = 0.04, kClosingShare = 0.33;

  explicit Blinking(std::uint64_t seed);
  /// Advances `dt_s`; `saccade_started_rad` is the amplitude of a saccade that
  /// started this step (0 if none).
  void step(double dt_s, float saccade_started_rad);
  /// Lid closure of the blink now, 0 .. 1.
  float closure() const;
  /// Whether a blink started in the last step.
  bool started() const { return started_; }
  int count() const { return count_; }
  /// The whole duration of the current (or last) blink, seconds.
  double duration_s() const { return duration_s_; }

 private:
  void start();
  double next_interval();
  double next_duration();

  std::mt19937_64 rng_;
  double since_last_s_ = 1e9;
  double until_next_s_;
  double blink_t_s_ = -1;  ///< time into the current blink, < 0: none
  double duration_s_ = kMedianBlinkS;
  bool started_ = false;
  int count_ = 0;
};

/// How far the upper lids close because the eyes look down (`eye_pitch_rad`
/// negative), 0 .. 0.45.
float lid_follows_pitch(float eye_pitch_rad);

}  // namespace fw::behavior
