#pragma once
// The behavior repertoire and its action selection ("Behavioral Animation of
// Faces", section 6): attentive, snubbing, visual search, expressive,
// mimicking and interactive routines; a mental state holding whether the face
// leads or follows; timers that keep any routine from lasting too long
// (behavior fatigue); and a person's commands, which win for their duration.
//
// The experiment of section 6.1: the leader searches until it sees another
// face, then attends to it and leads an expressive exchange (with several
// faces, it takes turns: interactive). A follower searches, attends to the
// leader when the leader attends to it, then mimics the leader's expression,
// until fatigue makes it disengage and attend to a different face.
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "fw/behavior/emotion_space.hpp"
#include "fw/behavior/expression_envelope.hpp"
#include "fw/behavior/perception.hpp"

namespace fw::behavior {

enum class Routine : std::uint8_t { visual_search, attentive, snubbing, expressive, mimicking, interactive };
std::string_view routine_name(Routine r);

/// What the face means to do this tick.
struct Intent {
  Routine routine = Routine::visual_search;
  std::optional<FaceId> attend;     ///< the face to look at
  glm::vec3 look_seat_mm{0.0f, 0.0f, 1200.0f};  ///< where to look when attending nobody
  std::optional<FaceId> mimic;      ///< the face whose emotion to follow
  /// An expression to start now.
  std::optional<Primary> perform;
  ExpressionEnvelope perform_envelope;
};

class ActionSelection {
 public:
  // Fatigue: the longest a routine may hold the same face.
  static constexpr double kLeaderTurnMinS = 3.0, kLeaderTurnMaxS = 7.0;  ///< interactive turns
  static constexpr double kAttendMaxS = 8.0;   ///< the leader on its only partner, then it glances away
  static constexpr double kGlanceAwayS = 1.5;
  static constexpr double kMimicMaxS = 5.0;    ///< a follower engaged with the leader
  static constexpr double kRestS = 4.0;        ///< a tired follower attends another face this long
  static constexpr double kEngageAfterS = 0.4; ///< attention returned this long becomes mimicry
  /// Visual search dwells this long on each point or face.
  static constexpr double kSearchDwellMinS = 0.5, kSearchDwellMaxS = 1.4;
  /// A snubbing face keeps its gaze at least this far from the snubbed one.
  static constexpr float kSnubClearanceRad = 0.52f;  ///< 30 degrees

  explicit ActionSelection(std::uint64_t seed);

  void set_leader(bool leader, std::optional<FaceId> leader_id);
  bool leader() const { return leader_; }

  /// A person's commands: they win over autonomy for `seconds`.
  void look_at(FaceId face, double seconds);
  void snub(FaceId face, double seconds);
  /// The person performs an expression: autonomous expressions and mimicry pause.
  void hold_expression(double seconds);
  /// Someone named this face in a chat line: look at them for `seconds`, as
  /// a command would (a person's command in force wins).
  void draw_attention(FaceId writer, double seconds);

  /// Decides this tick. `seen`: the faces perceived; `gaze`: where the eyes
  /// point now (seat frame); `performing`: an expression is under way;
  /// `felt`: what the face feels (its mood and the room's), which its
  /// displays show.
  Intent step(double dt_s, const std::vector<PerceivedFace>& seen, YawPitch gaze, bool performing,
              const EmotionPoint& felt);

  Routine routine() const { return routine_; }
  /// Whether a person's command (look at, snub) is in force: it wins over
  /// conversation too.
  bool commanded() const { return override_.has_value() && override_->until_s > now_s_; }
  std::optional<FaceId> attending() const { return attending_; }

 private:
  const PerceivedFace* find(const std::vector<PerceivedFace>& seen, std::optional<FaceId> id) const;
  bool clear_of(YawPitch candidate, const PerceivedFace* avoided) const;
  void search(Intent& intent, const std::vector<PerceivedFace>& seen, std::optional<FaceId> avoid);
  void lead(Intent& intent, const std::vector<PerceivedFace>& seen, bool performing, const EmotionPoint& felt);
  void follow(Intent& intent, const std::vector<PerceivedFace>& seen);
  void schedule_expression(Intent& intent, bool performing, const EmotionPoint& felt);
  double uniform(double lo, double hi);

  std::mt19937_64 rng_;
  bool leader_ = false;
  std::optional<FaceId> leader_id_;
  double now_s_ = 0;
  YawPitch gaze_{};
  Routine routine_ = Routine::visual_search;
  std::optional<FaceId> attending_;

  // Commands in force.
  struct Override {
    Routine routine;
    FaceId face;
    double until_s;
  };
  std::optional<Override> override_;
  double hold_expression_until_s_ = -1;

  // Visual search.
  glm::vec3 search_point_{0.0f, 0.0f, 1200.0f};
  std::optional<FaceId> search_face_;
  double search_until_s_ = -1;

  // Leader: the current partner, its turn, when each face was last attended.
  std::optional<FaceId> partner_;
  double partner_since_s_ = 0, turn_until_s_ = 0, glance_until_s_ = -1;
  std::vector<std::pair<FaceId, double>> last_attended_;
  double next_expression_s_ = 0;

  // Follower: engagement with the leader, then rest on another face.
  double engaged_since_s_ = -1;  ///< < 0: not engaged
  double rest_until_s_ = -1;
  std::optional<FaceId> rest_face_;
  double leader_attention_since_s_ = -1;
  double leader_away_since_s_ = -1;
};

}  // namespace fw::behavior
