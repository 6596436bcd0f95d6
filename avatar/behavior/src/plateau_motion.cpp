#include "fw/behavior/plateau_motion.hpp"

#include <algorithm>

#include "fw/behavior/gradient_noise.hpp"

namespace fw::behavior {

void add_plateau_motion(std::array<float, codec::kAuChannelCount>& au, double t_s, std::uint32_t seed) {
  // Gradient noise is zero at whole numbers: an offset per channel keeps
  // the channels from all passing through zero wavering at once.
  const auto t = static_cast<float>(t_s) * kPlateauMotionHz;
  for (std::size_t c = 0; c < au.size(); ++c) {
    if (au[c] < kPlateauMotionFrom) continue;
    const float noise = gradient_noise(t + 0.37f * static_cast<float>(c), seed + static_cast<std::uint32_t>(c) * 7919u);
    // Noise spans about [-0.5, 0.5]: twice it is the relative wavering.
    au[c] = std::clamp(au[c] * (1.0f + 2.0f * kPlateauMotionShare * noise), 0.0f, 1.0f);
  }
}

}  // namespace fw::behavior
