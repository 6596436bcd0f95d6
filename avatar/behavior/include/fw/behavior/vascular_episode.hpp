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

/// One avatar's vascular state: the episodes running, what causes them.
///
/// A blush has a social cause, not a few seconds of being looked at (in a
/// conversation someone always is): "acute self-consciousness" (section 4.1)
/// after a faux pas or in the spotlight. Leary, Britt, Cutlip & Templeton
/// (1992, "Social blushing", Psychological Bulletin 112) list both: being
/// embarrassed, and being the conspicuous centre of others' attention even
/// when the attention is positive. The audience deepens it (Shearn et al.
/// 1992, cited in section 6). Pallor comes with fear or shock (section 4.2).
class VascularState {
 public:
  /// Being the centre of attention this long starts a blush: at least
  /// kSpotlightFaces faces and at least half of the others attend this face
  /// at once, unbroken (a spotlight lasting longer than a listener's glance
  /// at a speaker, a few seconds; Argyle & Cook 1976).
  static constexpr double kSpotlightS = 8.0;
  static constexpr int kSpotlightFaces = 2;
  /// After a blush starts, no new one for this long.
  static constexpr double kBlushRefractoryS = 30.0;
  /// Fear above this (or surprise above kShockSurprise) pales the face.
  static constexpr float kPallorFear = 0.75f, kShockSurprise = 0.95f;
  /// After a pallor episode starts, no new one for this long.
  static constexpr double kPallorRefractoryS = 30.0;

  /// The audience-size effect (Shearn et al., cited in section 6): the blush
  /// grows with the number of faces attending, from 1 to 4 and saturating.
  static float audience_gain(int attending);
  /// A blush's span in seconds (Shields, Mallory & Simon 1990, cited in
  /// section 4.1: the median blush lasts ~20 s).
  static double blush_span_s(int attending);

  /// Advances `dt_s`. `attending`: faces whose gaze is on this one, of
  /// `others` in the room; `fear`, `surprise`: the face's emotion now.
  /// Returns what started, for the room's events ("blush start (...)").
  std::optional<std::string> step(double dt_s, int attending, int others, float fear, float surprise);
  /// The face is embarrassed now (its own chat line, say): a blush starts
  /// within the next step unless one is under way or was too recent
  /// (Shields et al. 1990: most blushes appear within 2 s of the stimulus).
  void embarrass();
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
  double spotlight_s_ = 0;  ///< how long the face has been the centre of attention
  bool embarrassed_ = false;
  double since_blush_s_ = 1e9;
  double since_pallor_s_ = 1e9;
};

}  // namespace fw::behavior
