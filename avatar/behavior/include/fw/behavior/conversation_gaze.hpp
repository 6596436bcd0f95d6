#pragma once
// Where a face looks while someone speaks: the gaze of conversation, as
// people do it, in place of the routines while a line is being said.
//
// - A listener looks at the speaker most of the utterance, about 75 %, in
//   glances of about 3 s with short looks away (Argyle & Cook 1976, "Gaze
//   and Mutual Gaze"; Argyle & Ingham 1972: mean glance 2.95 s).
// - The speaker looks at its listeners less, about 41 %, in shorter glances
//   and longer looks away (Argyle & Cook 1976); it looks away as a long
//   utterance begins, in over 70 % of them, and at a listener as it ends
//   (Kendon 1967, "Some functions of gaze-direction in social
//   interaction", Acta Psychologica 26), holding that look a moment after
//   its last word as the turn passes.
// - Mutual gaze comes of the two: episodes of a second or two (Argyle &
//   Ingham 1972: mean mutual glance 1.18 s; Rogers et al. 2018: ~2.2 s).
// - A listener turns to a new speaker with a human latency, a saccade's
//   200 ms or so (Carpenter 1988, "Movements of the Eyes"), each listener
//   drawing its own, so that they do not move in unison.
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "fw/behavior/perception.hpp"

namespace fw::behavior {

/// What a face knows of the conversation this tick.
struct ConversationScene {
  double now_s = 0;
  /// This face's own utterance, if it speaks: when it began and how long it lasts.
  std::optional<double> my_start_s, my_length_s;
  /// The speaker this face listens to (the one who began last), if any
  /// other face speaks, and when that utterance began.
  std::optional<FaceId> speaker;
  double speaker_start_s = 0;
};

/// What conversation asks of the eyes: a face, or a look away from it.
struct ConversationLook {
  std::optional<FaceId> attend;  ///< none: look away from `away_from`
  std::optional<FaceId> away_from;
  /// Where a look away goes beyond the edge of `away_from`'s face (the
  /// edge perception gives it, added by the caller, who knows how far the
  /// face is): a saccade of Eyes Alive's amplitudes and directions
  /// (ConversationGaze::kAwayAmplitudeRad, kAxisShare).
  YawPitch away_offset{};
};

class ConversationGaze {
 public:
  // Listener: glance at the speaker, look away (log-normal, medians):
  // about 75 % of the time on the speaker (Argyle & Cook 1976), in glances
  // near Argyle & Ingham's 2.95 s mean (1972).
  static constexpr double kListenGlanceS = 2.8, kListenAwayS = 0.9;
  // Speaker: glance at a listener, look away: shorter glances and longer
  // looks away, chosen so that with the end look below a speaker looks at
  // its listeners about 41 % of an utterance (Argyle & Cook 1976); the
  // conversation measures test holds the share.
  static constexpr double kSpeakGlanceS = 2.0, kSpeakAwayS = 3.6;
  static constexpr double kSpread = 0.4;  ///< sigma of log(duration)
  /// A long utterance, and how often it begins with the speaker looking away.
  static constexpr double kLongUtteranceS = 2.0, kStartAwayShare = 0.8;
  /// The last part of an utterance, in which the speaker looks at a
  /// listener (Kendon 1967: speakers look up as a long utterance ends).
  static constexpr double kEndLookS = 0.8;
  /// Reaction to a new speaker: mean and sigma of the latency, and its bounds.
  static constexpr double kLatencyS = 0.2, kLatencySpreadS = 0.05, kLatencyMinS = 0.12, kLatencyMaxS = 0.4;
  /// After the speaker stops, a listener keeps looking a moment, and so does
  /// the speaker at its last listener; then the routines take over again.
  static constexpr double kAfterS = 0.8;
  /// A listener whose glance would end while the speaker looks at it holds
  /// on up to this much longer.
  static constexpr double kHoldMutualS = 2.5;
  /// Mutual gaze the speaker holds once a listener returns its glance
  /// (log-normal median): between Argyle & Ingham's 1.18 s mean mutual
  /// glance (1972) and Rogers et al.'s 2.2 s mutual face gaze (2018).
  static constexpr double kMutualS = 1.6;
  /// A look away is a saccade, and saccades in conversation are mostly
  /// small: Lee, Badler & Badler ("Eyes Alive", SIGGRAPH 2002) found the
  /// share of saccades of amplitude A falling as e^(-A / 6.9 deg). A look
  /// away is one that leaves the face; the exponential has no memory, so
  /// its amplitude beyond the face's edge follows the same law (mean 6.9
  /// deg), up to the eyes' comfortable range.
  static constexpr float kAwayAmplitudeRad = 0.1204f, kAwayAmplitudeMaxRad = 0.5236f;  // 6.9 and 30 deg
  /// Eyes Alive's eight direction bins hold 70 % of saccades on the four
  /// axes (15.5-20.4 % each) and 30 % on the diagonals (6.5-7.9 % each).
  /// Here the axes share their 70 % evenly, and the diagonals their 30 %:
  /// the bins' differences within each group are small, and which way a
  /// look away goes is also bounded by the faces around (away_from_faces).
  static constexpr double kAxisShare = 0.704;

  explicit ConversationGaze(std::uint64_t seed);

  /// Decides this tick; none when conversation asks nothing (nobody
  /// speaks, or not yet: the latency), so that the routines decide.
  std::optional<ConversationLook> step(const ConversationScene& scene, const std::vector<PerceivedFace>& seen);

 private:
  double lognormal(double median);
  void draw_away_offset();
  std::optional<ConversationLook> listen(const ConversationScene& scene, const std::vector<PerceivedFace>& seen);
  std::optional<ConversationLook> speak(const ConversationScene& scene, const std::vector<PerceivedFace>& seen);
  std::optional<FaceId> next_listener(const std::vector<PerceivedFace>& seen);

  std::mt19937_64 rng_;
  // Listening: to whom, since when it reacts, and the glance/away phase.
  std::optional<FaceId> listening_to_;
  double listen_start_s_ = -1, react_at_s_ = 0;
  bool looking_ = true;
  double phase_until_s_ = 0;
  double after_until_s_ = -1;  ///< the speaker stopped: keep looking until then
  // Speaking: the utterance this face is in, its phase, its listener.
  double speech_start_s_ = -1;
  bool speaker_looking_ = false;
  double speaker_phase_until_s_ = 0;
  std::optional<FaceId> listener_;
  double mutual_until_s_ = -1;  ///< the listener returned the glance: hold it until then
  double handover_until_s_ = -1;  ///< the line ended: keep looking at `listener_` until then
  YawPitch away_offset_{};
};

}  // namespace fw::behavior
