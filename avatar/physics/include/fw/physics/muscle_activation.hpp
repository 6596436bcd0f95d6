#pragma once
// Kernel: the muscles' excitation-contraction lag, one first-order step
// toward the target, with the time constants SimulationOptions holds
// (15 ms up, 50 ms down: Winters 1995, Thelen 2003). The physics face
// drives its muscles with it; a room's face without tissue and the bench's
// kinematic track drive action units with it, so all three follow the
// same muscles.
#include <algorithm>
#include <cmath>

namespace fw::physics {

/// The share of the gap to its target an activation closes in one step,
/// rising and falling: 1 - e^(-h / tau).
struct ActivationRates {
  float rise = 1.0f;
  float fall = 1.0f;
};

/// @param[in] activation_time_s, deactivation_time_s  the time constants (under 0.1 ms taken as 0.1 ms)
/// @param[in] step_s  the step's length, seconds
inline ActivationRates activation_rates(float activation_time_s, float deactivation_time_s, float step_s) {
  return {1.0f - std::exp(-step_s / std::max(activation_time_s, 1e-4f)),
          1.0f - std::exp(-step_s / std::max(deactivation_time_s, 1e-4f))};
}

/// `current` one step closer to `target`.
inline float follow_activation(float current, float target, const ActivationRates& rates) {
  const float gap = target - current;
  return current + gap * (gap > 0.0f ? rates.rise : rates.fall);
}

}  // namespace fw::physics
