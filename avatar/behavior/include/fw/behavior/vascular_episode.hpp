#pragma once
// Vascular emotions ("A Computational Model for Vascular Expressions",
// sections 4-5, Figure 4): blushing and pallor as staged episodes, each
// stage a vascular expression (an intensity per colour region) reached over
// a percentage of the episode's span. Episodes are written in the face-script
// vascular language; the built-in ones follow the paper's blushing (stages of
// 10, 10, 60 and 20 percent).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/script/script_meaning.hpp"

namespace fw::behavior {

/// The built-in episodes as a face script (blushing, pallor).
std::string_view builtin_vascular_script();
/// A resolved episode of the built-in script by name ("blushing", "pallor").
const script::VascularEmotion& builtin_vascular_emotion(std::string_view name);

/// Colour channels (FaceParams::blush regions, then pallor) of `emotion`
/// `t_s` seconds into an episode lasting `span_s`, scaled by `gain`; zeros
/// outside the span.
script::ColourChannels episode_colour(const script::VascularEmotion& emotion, double t_s, double span_s, float gain);

/// One avatar's vascular state: the episodes running, what triggers them.
class VascularState {
 public:
  /// Being stared at this long starts a blush.
  static constexpr double kStareToBlushS = 2.0;
  /// After an episode, no new blush for this long.
  static constexpr double kBlushRefractoryS = 15.0;
  /// Fear above this (or surprise above kShockSurprise) pales the face.
  static constexpr float kPallorFear = 0.75f, kShockSurprise = 0.95f;
  /// After a pallor episode starts, no new one for this long.
  static constexpr double kPallorRefractoryS = 30.0;

  /// The audience-size effect (Shearn et al., cited in section 6): the blush
  /// grows with the number of faces attending, from 1 to 4 and saturating.
  static float audience_gain(int attending);
  /// A blush's span in seconds (the median blush lasts ~20 s).
  static double blush_span_s(int attending);

  /// Advances `dt_s`. `attending`: faces whose gaze is on this one; `point`:
  /// the face's emotion now. Returns the name of an episode that started.
  std::optional<std::string> step(double dt_s, int attending, float fear, float surprise);
  /// Starts an episode now (a script or a command), replacing one of the same name.
  void start(const script::VascularEmotion& emotion, double span_s, float gain);

  /// The face's colour now into FaceParams::blush and pallor.
  void write(codec::FaceParams& params) const;
  bool blushing() const;

 private:
  struct Episode {
    script::VascularEmotion emotion;
    double span_s;
    float gain;
    double t_s = 0;
  };
  std::vector<Episode> episodes_;
  double stared_s_ = 0;
  double since_blush_s_ = 1e9;
  double since_pallor_s_ = 1e9;
};

}  // namespace fw::behavior
