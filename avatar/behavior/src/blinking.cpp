#include "fw/behavior/blinking.hpp"

#include <algorithm>
#include <cmath>

namespace fw::behavior {

Blinking::Blinking(std::uint64_t seed) : rng_(seed) { until_next_s_ = next_interval(); }

double Blinking::next_interval() {
  // Poisson arrivals at the rest rate, beyond the refractory time.
  std::exponential_distribution<double> wait(kRestRatePerMin / 60.0);
  return kRefractoryS + wait(rng_) * (1.0 - kRefractoryS * kRestRatePerMin / 60.0);
}

double Blinking::next_duration() {
  std::lognormal_distribution<double> duration(std::log(kMedianBlinkS), kBlinkSpread);
  return std::clamp(duration(rng_), kShortestBlinkS, kLongestBlinkS);
}

void Blinking::start() {
  blink_t_s_ = 0;
  duration_s_ = next_duration();
  since_last_s_ = 0;
  started_ = true;
  ++count_;
  until_next_s_ = next_interval();
}

void Blinking::step(double dt_s, float saccade_started_rad) {
  started_ = false;
  since_last_s_ += dt_s;
  until_next_s_ -= dt_s;
  if (blink_t_s_ >= 0) {
    blink_t_s_ += dt_s;
    if (blink_t_s_ > duration_s_) blink_t_s_ = -1;
  }
  if (since_last_s_ < kRefractoryS) return;
  if (saccade_started_rad > kGazeBlinkFromRad) {
    // Gaze-evoked blinks grow likelier with the shift's size.
    const double p = std::min(0.7, 0.25 + (saccade_started_rad - kGazeBlinkFromRad) * 0.8);
    if (std::uniform_real_distribution<double>(0, 1)(rng_) < p) return start();
  }
  if (until_next_s_ <= 0) start();
}

float Blinking::closure() const {
  if (blink_t_s_ < 0) return 0;
  const double closing_s = kClosingShare * (duration_s_ - kClosedS);
  const double opening_s = duration_s_ - kClosedS - closing_s;
  if (blink_t_s_ < closing_s) return static_cast<float>(blink_t_s_ / closing_s);
  if (blink_t_s_ < closing_s + kClosedS) return 1;
  return static_cast<float>(std::max(0.0, 1 - (blink_t_s_ - closing_s - kClosedS) / opening_s));
}

float lid_follows_pitch(float eye_pitch_rad) { return std::clamp(-eye_pitch_rad * 0.9f, 0.0f, 0.45f); }

}  // namespace fw::behavior
