#pragma once
// A room's avatars simulated together, without any network: behavior
// (perception of the others, action selection, emotion, eye-head control,
// vascular episodes) sets each avatar's targets, the physics face turns the
// action-unit targets into a simulated surface, and the measured surface plus
// gaze, head, lids and colour make one FaceParams per avatar per tick.
//
// The room server runs one per room on its worker pool; `facewire-server
// simulate` runs one to record scenes. Not thread-safe: one caller at a time
// (the room's strand).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"
#include "track_maker.hpp"

namespace fw::physics {
class FaceSimulation;
}

namespace fw::server {

using AvatarId = std::uint32_t;

struct RoomSimulationOptions {
  std::uint64_t seed = 1;    ///< same seed and inputs, same faces
  int tick_hz = 30;          ///< ticks per simulated second
  bool physics = true;       ///< drive the AUs through the physics face
  bool physics_sleeps = true;  ///< a face at rest stops stepping until a target changes
  bool physics_projective = true;  ///< the physics face's solver: projective dynamics, else mass-spring (always in a preview)
  /// Seats laid out in the room (fw::behavior::seat_layout(seats); avatars
  /// take the first free one); 0: as many as avatars present, laid out again
  /// whenever one joins or leaves.
  int seats = 0;
  /// Avatar ids handed out: 1 .. id_space - 1 (the codec's 21 bits), each
  /// handed out again only after resting id_quiet_ticks since its avatar
  /// left (avatar_ids.hpp). Tests shrink both.
  AvatarId id_space = codec::kMaxAvatarIdValue + 1;
  std::uint64_t id_quiet_ticks = 60 * 30;
  /// The language chat lines are said in when their writer chose none (an
  /// espeak-ng language: en, de, fr, es, ...; spoken_lines.hpp), and the
  /// room's own faces' language.
  std::string speech_language = "en";
  /// Makes the lines' lip-sync tracks (track_maker.hpp); null: at once, on
  /// the caller's thread (ImmediateTrackMaker).
  std::shared_ptr<TrackMaker> track_maker{};
  /// A face-lab preview (PROTOCOL.md 5.16): every avatar's own behaviour
  /// starts off, and its person's overrides (face_overrides.hpp) hold its
  /// face; a room's avatars refuse overrides.
  bool preview = false;
};

struct FaceModel;  // face_model.hpp

struct AvatarSetup {
  std::string name;
  /// Nobody is at the keyboard: the behavior repertoire runs unattended.
  /// A person's avatar is autonomous too, but the person's commands win.
  bool person = true;
  /// The language the avatar's lines are said in; empty: the room's
  /// (RoomSimulationOptions::speech_language).
  std::string language = {};
  /// The avatar's asset id: its muscles' individual variation is drawn
  /// from it (avatar/physics muscle_variation.hpp), so it moves alike in
  /// every room; empty: from the room's seed and the avatar id.
  std::string asset = {};
  /// Its own face (face_models.hpp), when already built; null: the generic
  /// face until wear_face gives it its own.
  std::shared_ptr<const FaceModel> face = {};
};

/// A person's commands to their own avatar (they override autonomy for their
/// duration).
struct ExpressCommand {
  std::string emotion;      ///< joy, sadness, anger, fear, surprise, disgust, neutral
  float intensity = 1;      ///< 0 .. 1
  double seconds = 3;       ///< how long the expression is held
};
struct LookAtCommand {
  AvatarId target = 0;
  double seconds = 5;
};
struct SnubCommand {
  AvatarId target = 0;
  double seconds = 10;
};
struct FacsCommand {
  std::string sentence;     ///< a face script: an expression sentence, a vascular emotion, AU definitions (room_script.hpp)
};
/// A face-lab preview's override (face_overrides.hpp), held until changed.
struct OverrideCommand {
  codec::FaceOverride change;
};
/// A face script to parse without playing it (script_check.hpp).
struct CheckCommand {
  std::string script;
};
using AvatarCommand =
    std::variant<ExpressCommand, LookAtCommand, SnubCommand, FacsCommand, OverrideCommand, CheckCommand>;

/// Something that happened in the room at a tick (recorded in scenes,
/// logged by the server).
struct RoomEvent {
  std::uint32_t tick = 0;
  AvatarId avatar = 0;
  std::string what;         ///< e.g. "behavior attentive -> mimicking", "blush start", "chat"
  /// What the avatar's person should be told (a line said in part, or not
  /// said), "" for events that are only logged.
  std::string tell = {};
  /// The avatar began to say a chat line (PROTOCOL.md 5.15, speaking).
  struct LineBegun {
    std::uint32_t frame_tick = 0;   ///< the tick whose frame is the line's first (tick_index() after the next tick())
    std::uint32_t duration_ms = 0;  ///< the lip-sync track's length, at most codec::kMaxSpeakingMs
    std::string language;
    std::string text;               ///< the part of the line said
  };
  std::optional<LineBegun> line = {};
};

class RoomSimulation {
 public:
  explicit RoomSimulation(const RoomSimulationOptions& options);
  ~RoomSimulation();
  RoomSimulation(RoomSimulation&&) noexcept;
  RoomSimulation& operator=(RoomSimulation&&) noexcept;

  /// Seats a new avatar (the first one leads, as in the paper's experiment);
  /// 0 when the room is full or every id is in use or resting.
  AvatarId add_avatar(const AvatarSetup& setup);
  /// Seats an avatar under `id` (a room restored from another server);
  /// false if the id is taken or the room is full.
  bool restore_avatar(AvatarId id, const AvatarSetup& setup);
  /// The language `avatar`'s next lines are said in ("": the room's): a
  /// person taking a kept seat back may have chosen another.
  void set_language(AvatarId avatar, std::string language);
  /// An avatar's mood (one value per primary emotion), and that mood given
  /// back after a restore.
  std::vector<float> mood(AvatarId avatar) const;
  void set_mood(AvatarId avatar, const std::vector<float>& mood);
  /// Whether add_avatar would find an id now (false: all are in use or rest).
  bool has_free_id() const;
  void remove_avatar(AvatarId avatar);
  /// `avatar`'s own face, built off the room's strand after it joined
  /// (face_models.hpp): its physics face simulates that fit from the next
  /// tick on, measured against its own morphs, going on from where it is
  /// (no jump: what it shows goes over in kOwnFaceBlendS).
  void wear_face(AvatarId avatar, std::shared_ptr<const FaceModel> face);
  static constexpr double kOwnFaceBlendS = 1.0;
  /// Whether `avatar` simulates its own face (wear_face or AvatarSetup::face),
  /// not the generic one.
  bool wears_own_face(AvatarId avatar) const;
  std::vector<AvatarId> avatars() const;

  /// A person's command; an empty string when accepted, else why not (an
  /// unknown emotion, a target not in the room, a face script that does
  /// not parse (its line and column) or passes a room's bounds, an override
  /// outside a preview or of nothing the face has: the message says what
  /// was wrong). A check only parses its script.
  std::string command(AvatarId avatar, const AvatarCommand& command);
  /// A face script (a FacsCommand): its sentence and emotion played on the
  /// avatar's face, its AU definitions applied to the avatar's units
  /// (redefined_units.hpp; at most behavior::kMaxRedefinedUnitsPerAvatar at
  /// once), all or nothing. "" when taken, else what was wrong.
  std::string script(AvatarId avatar, std::string_view text);
  /// The avatar's redefined units as the unit morphs message carries them
  /// (server/PROTOCOL.md 5.17), its version raised by every change; nullopt
  /// while its person never redefined one. Forgotten when the avatar leaves.
  std::optional<codec::UnitMorphs> unit_morphs(AvatarId avatar) const;
  /// Gives `avatar` back the set a room's former owner kept for it
  /// (server/CLUSTER.md, a takeover), at its version: no budget is paid,
  /// nothing is played. "" when taken, else why not (RedefinedUnits::restore).
  std::string restore_unit_morphs(AvatarId avatar, const codec::UnitMorphs& set);
  /// A preview's (options.preview) simulated skin beyond what its frames'
  /// action units rebuild (preview_surface.hpp, PROTOCOL.md 5.18); nullopt
  /// in a room, or before the avatar's first tick.
  std::optional<codec::PreviewSurface> preview_surface(AvatarId avatar) const;
  /// A chat line from `avatar`: the avatar says it in its language (with
  /// lip sync, after the lines it is still saying, once the line's track is
  /// made; spoken_lines.hpp, track_maker.hpp), the others' gaze follows the
  /// speaker, the text nudges the writer's emotion. The line's start is an
  /// event with RoomEvent::line set.
  void chat(AvatarId avatar, std::string_view text);
  /// Whether the avatar is saying a line now.
  bool speaking(AvatarId avatar) const;

  /// Level of detail under load: the share (0 .. 1) of the room's faces that
  /// run the physics face from the next tick on. The others follow their
  /// action-unit targets kinematically (the muscles' activation time
  /// constants, no tissue). A face that gets physics back keeps that track
  /// until its tissue has caught up with it (at most a second) and then
  /// blends into the physics output over kPhysicsBlendS, so nothing jumps.
  /// Which faces keep physics is fixed per face (a hash of the seed and its
  /// id), so a face does not flicker between the two. Default 1.
  void set_physics_share(double share);
  /// Faces that ran the physics face in the last tick (awake or asleep),
  /// and faces that followed their targets without it.
  std::size_t physics_faces() const;
  std::size_t kinematic_faces() const;
  static constexpr double kPhysicsBlendS = 0.3;

  /// Advances every avatar by one tick: begin_tick, the faces' tissue
  /// stepped together on this thread, finish_tick.
  void tick();

  /// A tick in two halves, for a server that steps the faces of many rooms
  /// together (face_stepper.hpp). begin_tick runs behaviour and hands out
  /// the physics faces whose tissue needs a step of dt_s; whoever steps
  /// them (on any thread, with physics::step_together or a FacePool) must
  /// be done before finish_tick, which measures them and makes the faces.
  /// Between the two nothing else may be called on this simulation: the
  /// faces belong to the stepper until then. The faces come out the same
  /// as tick()'s, whatever else they are stepped with.
  struct TickFaces {
    std::vector<physics::FaceSimulation*> faces;
    double dt_s = 0;
  };
  TickFaces begin_tick();
  void finish_tick();
 private:
  /// Has the track of the waiting line of every avatar that is not
  /// speaking made; each line starts when its track is back.
  void say_waiting_lines();

 public:
  std::uint32_t tick_index() const;

  /// The avatar's face after the last tick.
  const codec::FaceParams& face(AvatarId avatar) const;
  /// Where the avatar sits (the layout changes as avatars join and leave).
  codec::SeatInfo seat(AvatarId avatar) const;
  /// Whom the avatar's face attends after the last tick: an avatar, the room
  /// (searching it), or nobody (a snub: it looks away from everyone).
  codec::Attention::Entry attention(AvatarId avatar) const;
  /// Whether the avatar's physics face sleeps (at rest, costs nothing).
  bool resting(AvatarId avatar) const;

  /// Events since the last call (moved out).
  std::vector<RoomEvent> take_events();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace fw::server
