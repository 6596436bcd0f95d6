#include "fw/behavior/emotion_state.hpp"

#include <algorithm>

namespace fw::behavior {

void EmotionState::express(Primary primary, const ExpressionEnvelope& envelope) {
  // A face performs one expression per primary at a time: the new one replaces it.
  std::erase_if(active_, [&](const Active& a) { return a.primary == primary; });
  active_.push_back({primary, envelope, 0});
}

void EmotionState::nudge(const EmotionPoint& delta) {
  for (std::size_t i = 0; i < kPrimaryCount; ++i) mood_[i] += delta[i];
  mood_ = clamp_to_cube(mood_);
}

void EmotionState::clear_expressions() { active_.clear(); }

void EmotionState::step(double dt_s) {
  for (Active& a : active_) a.t_s += dt_s;
  std::erase_if(active_, [](const Active& a) { return a.t_s >= a.envelope.length_s(); });
  mood_ = decay_toward_neutral(mood_, dt_s, kMoodHalfLifeS);
}

EmotionPoint EmotionState::point() const {
  EmotionPoint p = mood_;
  for (const Active& a : active_) {
    float& v = p[static_cast<std::size_t>(a.primary)];
    v = std::max(v, a.envelope.at(a.t_s));
  }
  return clamp_to_cube(p);
}

}  // namespace fw::behavior
