#pragma once
// Emotional mimicry: a face that attends to another takes on part of what it
// shows, later, selectively, and lets it go when it looks away.
//
// - Later: visible mimicry follows the display by about 0.5-1.5 s. Facial EMG
//   shows the first muscle response within 300-400 ms (Dimberg, Thunberg &
//   Elmehed 2000, "Unconscious facial reactions to emotional facial
//   expressions", Psychological Science 11); what an observer sees builds up
//   over the next second. Here: the display reaches the mimic after
//   kLatencyS and is approached with time constant kRiseS.
// - Partial and selective: people mimic smiles readily and anger hardly at
//   all; mimicry is a social signal of affiliation, not a copy (Hess &
//   Bourgeois 2010, "You smile - I smile", Biological Psychology 84; Hess &
//   Fischer 2013, "Emotional mimicry as social regulation", Personality and
//   Social Psychology Review 17). Gains per primary below, at most
//   kMaxGain.
// - It fades once the mimic stops attending (time constant kFadeS), instead
//   of lingering in the mood.
#include <deque>
#include <optional>

#include "fw/behavior/emotion_space.hpp"

namespace fw::behavior {

class Mimicry {
 public:
  static constexpr double kLatencyS = 0.6;
  static constexpr double kRiseS = 0.35;
  static constexpr double kFadeS = 0.6;
  static constexpr float kMaxGain = 0.55f;
  /// How much of each primary is taken on (joy, sadness, anger, fear,
  /// surprise, disgust): affiliative displays most, hostile ones not at all,
  /// sadness and fear a little (empathic concern).
  static constexpr EmotionPoint kGain = {kMaxGain, 0.2f, 0.0f, 0.15f, 0.4f, 0.0f};

  /// Advances `dt_s`. `attended`: what the face being mimicked shows now,
  /// none when this face mimics nobody.
  void step(double dt_s, const std::optional<EmotionPoint>& attended);
  /// What mimicry adds to the face's expression now.
  const EmotionPoint& point() const { return point_; }

 private:
  struct Seen {
    double at_s;
    EmotionPoint point;
  };
  double now_s_ = 0;
  std::deque<Seen> seen_;  ///< the displays of the last kLatencyS
  EmotionPoint point_{};
};

}  // namespace fw::behavior
