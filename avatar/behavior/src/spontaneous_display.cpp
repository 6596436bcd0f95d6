#include "fw/behavior/spontaneous_display.hpp"

#include <algorithm>

namespace fw::behavior {
namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

}  // namespace

Display spontaneous_display(const EmotionPoint& felt, std::mt19937_64& rng) {
  const auto strongest = std::max_element(felt.begin(), felt.end());
  if (*strongest > kFeltToShow) {
    // Shown as felt: the display's strength follows the feeling, with a
    // little play either way.
    const float intensity = std::clamp(*strongest * static_cast<float>(uniform(rng, 0.8, 1.2)), kFeltToShow, 1.0f);
    return {static_cast<Primary>(strongest - felt.begin()),
            envelope_for(uniform(rng, 1.2, 3.0), intensity, static_cast<float>(uniform(rng, 0.2, 0.6)))};
  }
  const auto smile = static_cast<float>(uniform(rng, kSocialSmileMin, kSocialSmileMax));
  return {Primary::joy, envelope_for(uniform(rng, 1.0, 2.5), smile, static_cast<float>(uniform(rng, 0.1, 0.4)))};
}

double next_display_after_s(std::mt19937_64& rng) { return uniform(rng, kDisplayIntervalMinS, kDisplayIntervalMaxS); }

}  // namespace fw::behavior
