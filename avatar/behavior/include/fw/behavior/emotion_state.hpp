#pragma once
// One face's emotional state: a mood point in expression space that decays
// toward neutral, plus the expressions being performed (each an envelope on
// one primary). What the face shows and what others perceive is their max.
#include <vector>

#include "fw/behavior/emotion_space.hpp"
#include "fw/behavior/expression_envelope.hpp"

namespace fw::behavior {

class EmotionState {
 public:
  /// Half-life of the mood's return to neutral.
  static constexpr double kMoodHalfLifeS = 4.0;

  /// Performs `primary` along `envelope`, starting now.
  void express(Primary primary, const ExpressionEnvelope& envelope);
  /// Adds `delta` to the mood (an appraisal); the cube bounds it.
  void nudge(const EmotionPoint& delta);
  /// Ends every performed expression (a person's command takes over).
  void clear_expressions();
  /// Back to neutral at once: no mood, no expression.
  void reset() { mood_ = {}; active_.clear(); }
  /// Advances time: envelopes run, the mood decays.
  void step(double dt_s);

  /// The point shown and perceived.
  EmotionPoint point() const;
  const EmotionPoint& mood() const { return mood_; }
  bool performing() const { return !active_.empty(); }

 private:
  struct Active {
    Primary primary;
    ExpressionEnvelope envelope;
    double t_s = 0;
  };
  EmotionPoint mood_{};
  std::vector<Active> active_;
};

}  // namespace fw::behavior
