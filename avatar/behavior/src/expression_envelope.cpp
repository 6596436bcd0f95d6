#include "fw/behavior/expression_envelope.hpp"

#include <algorithm>

namespace fw::behavior {
namespace {

// Smooth ease (3s^2 - 2s^3): faces speed up and slow down, never jump.
float ease(double s) {
  const double c = std::clamp(s, 0.0, 1.0);
  return static_cast<float>(c * c * (3 - 2 * c));
}

}  // namespace

float ExpressionEnvelope::at(double t) const {
  if (t < 0) return 0;
  const float held = peak * sustain_level;
  if (t < attack_s) return peak * ease(t / attack_s);
  t -= attack_s;
  if (t < decay_s) return peak + (held - peak) * ease(t / decay_s);
  t -= decay_s;
  if (t < sustain_s) return held;
  t -= sustain_s;
  if (t < release_s) return held * (1 - ease(t / release_s));
  return 0;
}

ExpressionEnvelope envelope_for(double seconds, float intensity, float emphasis) {
  emphasis = std::clamp(emphasis, 0.0f, 1.0f);
  intensity = std::clamp(intensity, 0.0f, 1.0f);
  ExpressionEnvelope e;
  e.attack_s = 0.45 - 0.3 * emphasis;  // an emphatic expression snaps on
  e.decay_s = std::min(0.4, std::max(0.0, seconds) * 0.3);
  e.sustain_s = std::max(0.0, seconds - e.decay_s);
  e.release_s = 0.8;
  e.sustain_level = 1.0f - 0.3f * emphasis;
  // The apex overshoots the held level; the held level is what was asked.
  e.peak = std::min(1.0f, intensity / e.sustain_level);
  e.sustain_level = e.peak > 0 ? intensity / e.peak : 1.0f;
  return e;
}

}  // namespace fw::behavior
