#include "fw/behavior/mimicry.hpp"

#include <cmath>

namespace fw::behavior {

void Mimicry::step(double dt_s, const std::optional<EmotionPoint>& attended) {
  now_s_ += dt_s;
  if (attended) {
    seen_.push_back({now_s_, *attended});
  } else {
    seen_.clear();  // looking away: what was on its way is not taken on
  }
  // Keep the newest display that is at least kLatencyS old at the front:
  // that is the one reaching the mimic now.
  while (seen_.size() >= 2 && now_s_ - seen_[1].at_s >= kLatencyS) seen_.pop_front();
  EmotionPoint goal{};
  if (!seen_.empty() && now_s_ - seen_.front().at_s >= kLatencyS)
    for (std::size_t k = 0; k < kPrimaryCount; ++k) goal[k] = kGain[k] * seen_.front().point[k];
  const double tau = attended ? kRiseS : kFadeS;
  const auto rate = static_cast<float>(1 - std::exp(-dt_s / tau));
  for (std::size_t k = 0; k < kPrimaryCount; ++k) point_[k] += (goal[k] - point_[k]) * rate;
}

}  // namespace fw::behavior
