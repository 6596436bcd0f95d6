#pragma once
// An expression's course in time: attack to its apex, decay to the sustained
// level, sustain, release to nothing (the four stages FACS and the vascular
// paper use for an emotional episode).
namespace fw::behavior {

struct ExpressionEnvelope {
  double attack_s = 0.3;     ///< 0 -> peak
  double decay_s = 0.3;      ///< peak -> sustain level
  double sustain_s = 2.0;    ///< held at the sustain level
  double release_s = 0.8;    ///< sustain level -> 0
  float peak = 1;            ///< apex intensity, 0 .. 1
  float sustain_level = 0.8; ///< fraction of the peak held

  double length_s() const { return attack_s + decay_s + sustain_s + release_s; }
  /// Intensity `t_s` seconds after the start; 0 before and after.
  float at(double t_s) const;
};

/// The envelope of a command "show this for `seconds`, with `emphasis`"
/// (0 .. 1): more emphasis means a faster attack, a higher apex above the
/// held level. The held part (decay + sustain) lasts `seconds`.
ExpressionEnvelope envelope_for(double seconds, float intensity, float emphasis);

}  // namespace fw::behavior
