#pragma once
// The behavior of every face of a room, tick by tick: each face perceives the
// others through the room's snapshot of the previous tick, selects an action,
// and its motor layer (emotion and expressions, eye-head coordination, blinks,
// vascular episodes) produces the targets of its FaceParams: action-unit
// targets for the physics face, and the head, gaze, lids and colour as they
// are.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fw/behavior/action_selection.hpp"
#include "fw/behavior/emotion_space.hpp"
#include "fw/behavior/facs_track.hpp"
#include "fw/behavior/room_script.hpp"
#include "fw/behavior/perception.hpp"
#include "fw/behavior/seat_layout.hpp"
#include "fw/codec/face_params.hpp"

namespace fw::behavior {

/// How long `text` takes to say when there is no speech track for it: by
/// its words, at about 2.5 a second, 0.8 to 15 s.
double estimated_speech_s(std::string_view text);

struct BehaviorRoomOptions {
  std::uint64_t seed = 1;
  int tick_hz = 30;
  /// Seats laid out; 0: as many as faces present, laid out again as they come
  /// and go. Faces beyond the seats are refused.
  int seats = 0;
  bool micro_movements = true;  ///< fixation drift, tremor, micro-saccades
  bool head_noise = true;       ///< Perlin noise on the heads
};

struct BehaviorEvent {
  FaceId face = 0;
  std::string what;
};

class BehaviorRoom {
 public:
  static constexpr int kMaxFaces = 64;

  explicit BehaviorRoom(const BehaviorRoomOptions& options);
  ~BehaviorRoom();
  BehaviorRoom(BehaviorRoom&&) noexcept;
  BehaviorRoom& operator=(BehaviorRoom&&) noexcept;

  /// Seats face `id` (unique; the first present leads). False if the room is full
  /// or the id is taken.
  bool add(FaceId id, std::string name);
  void remove(FaceId id);
  bool contains(FaceId id) const;
  std::vector<FaceId> faces() const;

  // A person's commands; each returns "" when accepted, else what was wrong.
  std::string look_at(FaceId face, FaceId target, double seconds);
  std::string snub(FaceId face, FaceId target, double seconds);
  /// `emotion`: a primary's name or "neutral"; intensity 0..1; seconds 0..60.
  std::string express(FaceId face, std::string_view emotion, float intensity, double seconds);
  /// A face script (room_script.hpp): its expression sentence played over
  /// autonomy (KeepAllFrame from the face as it is), its vascular emotion
  /// as an episode of kRoomScriptEpisodeS on this face alone. The error,
  /// if any, gives the script's line and column or the bound it passes.
  std::string facs(FaceId face, std::string_view script);
  /// A script already read (read_room_script): its sentence and emotion
  /// played as above. Its AU definitions are the caller's to apply (they
  /// change the face's model, which the room's physics and clients hold).
  std::string facs(FaceId face, const RoomScript& script);
  /// The face's mood (the emotion it holds between expressions), and that
  /// mood given back: a room restored on another server keeps its moods.
  EmotionPoint mood(FaceId face) const;
  void set_mood(FaceId face, const EmotionPoint& mood);
  /// A chat line: the writer says it, which the others' gaze follows
  /// (conversation_gaze.hpp), and the text nudges the writer's mood.
  /// `mouth`: the line's lip-sync track, whose jaw and lip channels the
  /// face shows while it speaks; without one the face speaks for as long
  /// as the line would take (estimated_speech_s) with a still mouth.
  void chat(FaceId face, std::string_view text, const AuTrack* mouth = nullptr);
  /// Whether the face is saying a line now.
  bool speaking(FaceId face) const;
  /// The jaw and lip targets its speech track sets this tick (articulation.hpp),
  /// if it says a line with one: a physics face downstream, too slow for
  /// syllables, shows these channels as they are.
  const std::optional<AuTargets>& articulation(FaceId face) const;

  void tick();
  std::uint32_t tick_index() const;
  double dt_s() const;

  /// The targets after the last tick: AUs as the behavior wants them.
  const codec::FaceParams& face(FaceId id) const;
  const FaceSnapshot& snapshot(FaceId id) const;
  Routine routine(FaceId id) const;
  std::optional<FaceId> attending(FaceId id) const;
  bool leader(FaceId id) const;
  Seat seat(FaceId id) const;
  /// Gaze of the face's eyes in its seat frame (head + eye).
  YawPitch gaze(FaceId id) const;
  int blinks(FaceId id) const;

  std::vector<BehaviorEvent> take_events();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fw::behavior
