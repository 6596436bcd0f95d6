#include "fw/behavior/behavior_room.hpp"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "fw/behavior/articulation.hpp"
#include "fw/behavior/blinking.hpp"
#include "fw/behavior/chat_appraisal.hpp"
#include "fw/behavior/emotion_state.hpp"
#include "fw/behavior/eye_head.hpp"
#include "fw/behavior/conversation_gaze.hpp"
#include "fw/behavior/face_scan.hpp"
#include "fw/behavior/facs_track.hpp"
#include "fw/behavior/mimicry.hpp"
#include "fw/behavior/room_script.hpp"
#include "fw/behavior/vascular_episode.hpp"

namespace fw::behavior {
namespace {

/// Whoever is named in a line looks at its writer through it and a moment
/// after: being addressed calls for an answer (a look now; words are the
/// person's).
constexpr double kNamedAttentionAfterS = 1.5;
/// A line's length when the caller has no speech track for it: English at
/// about 2.5 words a second (150 words a minute), within 0.8-15 s.
constexpr double kWordsPerSecond = 2.5, kShortestLineS = 0.8, kLongestLineS = 15.0;
/// How much of a chat line's appraisal colours the room's mood, and how
/// fast the room forgets it: a conversation's tone outlasts a single line's
/// expression (mood half-life 4 s) but not by minutes.
constexpr float kRoomMoodShare = 0.5f;
constexpr double kRoomMoodHalfLifeS = 30.0;
constexpr double kMaxCommandS = 600;
constexpr double kShortestBlushS = 6.0;  ///< a commanded blush rises, holds and fades in no less

std::uint64_t mix(std::uint64_t x) {  // splitmix64: one independent stream per face and part
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Whether `text` names `name` (ASCII case ignored, as a whole word: "ann"
// in "Hi Ann!" but not in "annoying").
bool names(std::string_view text, std::string_view name) {
  if (name.empty() || name.size() > text.size()) return false;
  const auto lower = [](char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); };
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || (c & 0x80) != 0; };
  for (std::size_t at = 0; at + name.size() <= text.size(); ++at) {
    bool same = true;
    for (std::size_t i = 0; i < name.size() && same; ++i) same = lower(text[at + i]) == lower(name[i]);
    const bool alone = (at == 0 || !word(text[at - 1])) && (at + name.size() == text.size() || !word(text[at + name.size()]));
    if (same && alone) return true;
  }
  return false;
}

}  // namespace

struct BehaviorRoom::Impl {
  struct Face {
    Face(FaceId face_id, std::string face_name, std::uint64_t seed, const BehaviorRoomOptions& o)
        : id(face_id), name(std::move(face_name)), mind(mix(seed + 1)),
          eyes({mix(seed + 2), o.micro_movements, o.head_noise}), blink(mix(seed + 3)), talk(mix(seed + 4)),
          scan(mix(seed + 5)) {}
    FaceId id;
    std::string name;
    std::uint64_t joined = 0;  ///< join order: the earliest present leads
    std::size_t seat = 0;
    ActionSelection mind;
    EmotionState emotion;
    Mimicry mimic;
    EyeHeadController eyes;
    Blinking blink;
    VascularState vascular;
    std::optional<AuTrack> facs;
    double facs_t_s = 0;
    /// The expression's AU targets after the last tick, speech aside: the
    /// face a KeepAllFrame sentence keeps (a line's jaw is not kept).
    AuTargets expression_au{};
    ConversationGaze talk;
    FaceScan scan;
    // The line being said: since when (room time), how long, and its mouth.
    std::optional<double> speech_start_s;
    double speech_length_s = 0;
    std::optional<AuTrack> speech_mouth;
    std::optional<FaceId> attending;  ///< whom the eyes are sent to this tick (routine or conversation)
    std::optional<AuTargets> articulation;  ///< the speech track's jaw and lips this tick
    FaceSnapshot snapshot;
    codec::FaceParams params;
    Routine shown_routine = Routine::visual_search;
    std::optional<FaceId> shown_attend;
    bool shown_leader = false;
  };

  BehaviorRoomOptions options;
  std::vector<Face> faces;  ///< in join order
  EmotionPoint room_mood{};  ///< the tone of the room's chat (kRoomMoodShare of each line), decaying
  std::vector<Seat> seats;
  std::uint32_t tick = 0;
  std::uint64_t joins = 0;
  std::vector<BehaviorEvent> events;

  double dt() const { return 1.0 / options.tick_hz; }
  double now_s() const { return tick * dt(); }

  Face* find(FaceId id) {
    for (Face& f : faces)
      if (f.id == id) return &f;
    return nullptr;
  }
  const Face& get(FaceId id) const {
    for (const Face& f : faces)
      if (f.id == id) return f;
    assert(false && "no such face in the room");
    std::abort();
  }
  std::string name_of(FaceId id) {
    const Face* f = find(id);
    return f ? f->name : std::string("#") + std::to_string(id);
  }
  void event(FaceId id, std::string what) { events.push_back({id, std::move(what)}); }

  void lay_out() {
    const int count = options.seats > 0 ? options.seats : static_cast<int>(faces.size());
    seats = seat_layout(std::max(count, 1));
    if (options.seats <= 0)
      for (std::size_t i = 0; i < faces.size(); ++i) faces[i].seat = i;
    for (Face& f : faces) {
      f.snapshot.seat = seats[f.seat];
      refresh_snapshot(f);
    }
    // The first face present leads (section 6.1).
    for (std::size_t i = 0; i < faces.size(); ++i) {
      Face& f = faces[i];
      const bool leads = i == 0;
      f.mind.set_leader(leads, faces.front().id);
      if (leads && !f.shown_leader) event(f.id, "leads");
      f.shown_leader = leads;
    }
  }

  void refresh_snapshot(Face& f) {
    FaceSnapshot& s = f.snapshot;
    s.id = f.id;
    const HeadPose head = f.eyes.head();
    s.eye_mid_room_mm = seat_to_room(s.seat, f.eyes.eye_position_seat());
    s.mouth_room_mm = seat_to_room(s.seat, head_to_seat(head, head_geometry().mouth_mm));
    const glm::vec3 dir_seat = direction_from_angles(f.eyes.gaze());
    s.gaze_direction_room = glm::normalize(seat_to_room(s.seat, dir_seat) - s.seat.origin_mm);
    s.head_yaw_rad = head.yaw_rad;
    s.emotion = shown_emotion(f);
    s.emotion_template = classify(s.emotion);
    s.speaking_since_s = f.speech_start_s;
  }

  // What the face shows and others perceive: its own emotion, and what it
  // takes on from the face it mimics.
  static EmotionPoint shown_emotion(const Face& f) {
    EmotionPoint point = f.emotion.point();
    for (std::size_t k = 0; k < kPrimaryCount; ++k) point[k] = std::max(point[k], f.mimic.point()[k]);
    return point;
  }

  // While anyone speaks, conversation decides where the face looks
  // (conversation_gaze.hpp); its routine still decides what it shows.
  void converse(Face& f, const std::vector<FaceSnapshot>& room, const std::vector<PerceivedFace>& seen,
                Intent& intent) {
    ConversationScene scene;
    scene.now_s = now_s();
    if (f.speech_start_s) {
      scene.my_start_s = f.speech_start_s;
      scene.my_length_s = f.speech_length_s;
    }
    for (const FaceSnapshot& s : room)
      if (s.id != f.id && s.speaking_since_s && (!scene.speaker || *s.speaking_since_s >= scene.speaker_start_s)) {
        scene.speaker = s.id;
        scene.speaker_start_s = *s.speaking_since_s;
      }
    const std::optional<ConversationLook> look = f.talk.step(scene, seen);
    if (!look) return;
    if (look->attend) {
      intent.attend = look->attend;
      if (intent.routine == Routine::visual_search) intent.routine = Routine::attentive;
    } else {
      intent.attend.reset();
      intent.routine = Routine::visual_search;
      YawPitch from{};
      float face_radius_rad = 0;
      for (const FaceSnapshot& s : room)
        if (look->away_from && s.id == *look->away_from) {
          const glm::vec3 to_face = room_to_seat(f.snapshot.seat, s.eye_mid_room_mm) - f.eyes.eye_position_seat();
          from = direction_angles(to_face);
          // The face as perception bounds it (face_on_gaze): its area, or
          // the attention cone about its eyes, whichever is wider.
          face_radius_rad = std::max(kAttendConeRad, std::atan2(kFaceAreaRadiusMm, glm::length(to_face)));
        }
      const YawPitch away = away_from_faces(f, from, beyond_face_edge(look->away_offset, face_radius_rad), room);
      intent.look_seat_mm = f.eyes.eye_position_seat() + 1500.0f * direction_from_angles(away);
    }
    // Mimicry needs the mimicked face in view of the eyes, not just in mind.
    if (intent.mimic && intent.attend != intent.mimic) intent.mimic.reset();
  }

  // `offset` (a saccade's amplitude beyond the face's edge) lengthened by
  // the face's own angular radius, so that the look leaves the face.
  static YawPitch beyond_face_edge(YawPitch offset, float face_radius_rad) {
    const float amplitude = std::hypot(offset.yaw_rad, offset.pitch_rad);
    if (amplitude <= 0.0f) return {0.0f, -face_radius_rad};
    const float scale = (amplitude + face_radius_rad) / amplitude;
    return {offset.yaw_rad * scale, offset.pitch_rad * scale};
  }

  // A look away rests on no face: the drawn offset from `from`, else its
  // mirror images, else as far straight down or up, else twice as far down
  // (below the ring of faces).
  static YawPitch away_from_faces(const Face& f, YawPitch from, YawPitch offset,
                                  const std::vector<FaceSnapshot>& room) {
    const glm::vec3 eyes_room = f.snapshot.eye_mid_room_mm;
    const auto on_a_face = [&](YawPitch a) {
      const glm::vec3 d = seat_to_room(f.snapshot.seat, direction_from_angles(a)) - f.snapshot.seat.origin_mm;
      return face_on_gaze(f.id, eyes_room, glm::normalize(d), room).has_value();
    };
    const float amplitude = std::hypot(offset.yaw_rad, offset.pitch_rad);
    const YawPitch candidates[] = {{from.yaw_rad + offset.yaw_rad, from.pitch_rad + offset.pitch_rad},
                                   {from.yaw_rad - offset.yaw_rad, from.pitch_rad + offset.pitch_rad},
                                   {from.yaw_rad + offset.yaw_rad, from.pitch_rad - offset.pitch_rad},
                                   {from.yaw_rad - offset.yaw_rad, from.pitch_rad - offset.pitch_rad},
                                   {from.yaw_rad, from.pitch_rad - amplitude},
                                   {from.yaw_rad, from.pitch_rad + amplitude},
                                   {from.yaw_rad, from.pitch_rad - 2 * amplitude}};
    for (const YawPitch& a : candidates)
      if (!on_a_face(a)) return a;
    return candidates[6];
  }

  // The line being said: its track moves the jaw and lips (articulation
  // wins there over the expression; the rest of the face keeps it); it
  // ends on time.
  void speak_tick(Face& f, codec::FaceParams& p) {
    f.articulation.reset();
    if (!f.speech_start_s) return;
    const double t = now_s() - *f.speech_start_s;
    if (t >= f.speech_length_s) {
      f.speech_start_s.reset();
      f.speech_mouth.reset();
      return;
    }
    if (!f.speech_mouth) return;
    f.articulation = f.speech_mouth->at(t);
    articulate(p.au, *f.articulation);
  }

  void step_face(Face& f, const std::vector<FaceSnapshot>& room) {
    const double dt_s = dt();
    const std::vector<PerceivedFace> seen = perceive(f.snapshot, room);
    EmotionPoint felt = f.emotion.mood();
    for (std::size_t k = 0; k < kPrimaryCount; ++k) felt[k] = std::max(felt[k], room_mood[k]);
    Intent intent = f.mind.step(dt_s, seen, f.eyes.gaze(), f.emotion.performing(), felt);
    if (!f.mind.commanded()) converse(f, room, seen, intent);
    f.attending = intent.attend;
    if (intent.perform) f.emotion.express(*intent.perform, intent.perform_envelope);
    std::optional<EmotionPoint> mimicked;
    for (const PerceivedFace& p : seen)
      if (intent.mimic && p.id == *intent.mimic) mimicked = p.emotion;
    f.mimic.step(dt_s, mimicked);
    f.emotion.step(dt_s);

    glm::vec3 target = intent.look_seat_mm;
    const FaceSnapshot* attended = nullptr;
    for (const FaceSnapshot& s : room)
      if (intent.attend && s.id == *intent.attend) attended = &s;
    const FacePoint point_on_face =
        f.scan.step(now_s(), attended ? std::optional(attended->id) : std::nullopt,
                    attended && attended->speaking_since_s.has_value());
    if (attended) target = room_to_seat(f.snapshot.seat, face_point_room(*attended, point_on_face));
    f.eyes.look_at(target);
    f.eyes.step(dt_s);
    f.blink.step(dt_s, f.eyes.saccade_started_rad());
    const EmotionPoint point = shown_emotion(f);
    const int others = static_cast<int>(faces.size()) - 1;
    if (auto started = f.vascular.step(dt_s, attending_count(f.id, room), others,
                                       point[static_cast<std::size_t>(Primary::fear)],
                                       point[static_cast<std::size_t>(Primary::surprise)]))
      event(f.id, *started);

    codec::FaceParams p;
    float expression_lids = 0;
    p.au = emotion_action_units(point, &expression_lids);
    if (f.facs) {
      // The person's FACS sentence wins over the autonomous expression.
      f.facs_t_s += dt_s;
      p.au = f.facs->at(f.facs_t_s);
      if (f.facs_t_s >= f.facs->length_s()) f.facs.reset();
    }
    f.expression_au = p.au;
    speak_tick(f, p);
    f.eyes.write(p);
    const float pitch_lids = lid_follows_pitch(f.eyes.eye().pitch_rad);
    p.lid_left = p.lid_right = std::max(f.blink.closure(), std::min(1.0f, expression_lids + pitch_lids));
    f.vascular.write(p);
    f.params = p;

    if (intent.routine != f.shown_routine || intent.attend != f.shown_attend) {
      std::string what = std::string("behavior ") + std::string(routine_name(f.shown_routine)) + " -> " +
                         std::string(routine_name(intent.routine));
      if (intent.attend) {
        what += " (";
        what += name_of(*intent.attend);
        what += ")";
      }
      // Visual search hops between faces every second: log its start only.
      if (intent.routine != f.shown_routine || intent.routine != Routine::visual_search) event(f.id, what);
      f.shown_routine = intent.routine;
      f.shown_attend = intent.attend;
    }
  }

  void step() {
    std::vector<FaceSnapshot> room;
    room.reserve(faces.size());
    for (const Face& f : faces) room.push_back(f.snapshot);
    room_mood = decay_toward_neutral(room_mood, dt(), kRoomMoodHalfLifeS);
    for (Face& f : faces) step_face(f, room);
    for (Face& f : faces) refresh_snapshot(f);
    // Who looks at whom, from the gaze just computed.
    std::vector<FaceSnapshot> now;
    for (const Face& f : faces) now.push_back(f.snapshot);
    for (Face& f : faces)
      f.snapshot.looking_at = face_on_gaze(f.id, f.snapshot.eye_mid_room_mm, f.snapshot.gaze_direction_room, now);
    ++tick;
  }
};

BehaviorRoom::BehaviorRoom(const BehaviorRoomOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  impl_->options.tick_hz = std::clamp(options.tick_hz, 1, 240);
  impl_->options.seats = std::clamp(options.seats, 0, kMaxFaces);
  impl_->lay_out();
}
BehaviorRoom::~BehaviorRoom() = default;
BehaviorRoom::BehaviorRoom(BehaviorRoom&&) noexcept = default;
BehaviorRoom& BehaviorRoom::operator=(BehaviorRoom&&) noexcept = default;

bool BehaviorRoom::add(FaceId id, std::string name) {
  Impl& r = *impl_;
  const int limit = r.options.seats > 0 ? r.options.seats : kMaxFaces;
  if (r.find(id) || static_cast<int>(r.faces.size()) >= limit) return false;
  r.faces.emplace_back(id, std::move(name), mix(r.options.seed ^ (std::uint64_t{id} << 20)), r.options);
  Impl::Face& f = r.faces.back();
  f.joined = r.joins++;
  if (r.options.seats > 0) {
    // The first free seat.
    for (std::size_t s = 0; s < static_cast<std::size_t>(r.options.seats); ++s) {
      if (std::none_of(r.faces.begin(), r.faces.end() - 1, [&](const Impl::Face& o) { return o.seat == s; })) {
        f.seat = s;
        break;
      }
    }
  }
  r.event(id, "joins");
  r.lay_out();
  return true;
}

void BehaviorRoom::remove(FaceId id) {
  Impl& r = *impl_;
  if (!r.find(id)) return;
  std::erase_if(r.faces, [&](const Impl::Face& f) { return f.id == id; });
  r.event(id, "leaves");
  r.lay_out();
}

bool BehaviorRoom::contains(FaceId id) const { return impl_->find(id) != nullptr; }

std::vector<FaceId> BehaviorRoom::faces() const {
  std::vector<FaceId> ids;
  for (const auto& f : impl_->faces) ids.push_back(f.id);
  return ids;
}

namespace {
std::string check_seconds(double seconds) {
  if (!(seconds > 0 && seconds <= kMaxCommandS)) return "seconds must be more than 0 and at most 600";
  return {};
}
}  // namespace

std::string BehaviorRoom::look_at(FaceId face, FaceId target, double seconds) {
  Impl::Face* f = impl_->find(face);
  if (!f) return std::string("no avatar ") + std::to_string(face) + " in this room";
  if (!impl_->find(target) || target == face) return std::string("avatar ") + std::to_string(target) + " is not another face in this room";
  if (auto e = check_seconds(seconds); !e.empty()) return e;
  f->mind.look_at(target, seconds);
  impl_->event(face, std::string("command look at ") + impl_->name_of(target));
  return {};
}

std::string BehaviorRoom::snub(FaceId face, FaceId target, double seconds) {
  Impl::Face* f = impl_->find(face);
  if (!f) return std::string("no avatar ") + std::to_string(face) + " in this room";
  if (!impl_->find(target) || target == face) return std::string("avatar ") + std::to_string(target) + " is not another face in this room";
  if (auto e = check_seconds(seconds); !e.empty()) return e;
  f->mind.snub(target, seconds);
  impl_->event(face, std::string("command snub ") + impl_->name_of(target));
  return {};
}

std::string BehaviorRoom::express(FaceId face, std::string_view emotion, float intensity, double seconds) {
  Impl::Face* f = impl_->find(face);
  if (!f) return std::string("no avatar ") + std::to_string(face) + " in this room";
  if (auto e = check_seconds(seconds); !e.empty()) return e;
  if (!(intensity >= 0 && intensity <= 1)) return "intensity must be between 0 and 1";
  if (emotion == "neutral") {
    f->emotion.reset();
    f->facs.reset();
  } else if (emotion == "blush") {
    // A blush is colour, not a pose: the vascular episode a stare would
    // start, at the asked strength; its stages need a few seconds to show.
    f->vascular.start(builtin_vascular_emotion("blushing"), std::max(seconds, kShortestBlushS), intensity);
    impl_->event(face, "command express blush");
    return {};
  } else if (const auto primary = primary_from_name(emotion)) {
    f->emotion.reset();
    f->emotion.express(*primary, envelope_for(seconds, intensity, 0.6f));
  } else if (const auto expression = model::expression_from_name(emotion)) {
    // Cunning and teasing have no place in the emotion space: played as a
    // track of their action units, as a FACS sentence would be.
    f->emotion.reset();
    f->facs = expression_track(*expression, intensity, seconds);
    f->facs_t_s = 0;
  } else {
    return std::string("unknown emotion '") + std::string(emotion) +
           "' (use joy, sadness, anger, fear, surprise, disgust, cunning, teasing, blush or neutral)";
  }
  f->mind.hold_expression(seconds + 1.0);
  impl_->event(face, std::string("command express ") + std::string(emotion));
  return {};
}

std::string BehaviorRoom::facs(FaceId face, std::string_view script) {
  Impl::Face* f = impl_->find(face);
  if (!f) return std::string("no avatar ") + std::to_string(face) + " in this room";
  RoomScript read;
  if (std::string error = read_room_script(script, read); !error.empty()) return error;
  return facs(face, read);
}

std::string BehaviorRoom::facs(FaceId face, const RoomScript& read) {
  Impl::Face* f = impl_->find(face);
  if (!f) return std::string("no avatar ") + std::to_string(face) + " in this room";
  std::string what = "command script";
  if (read.animation) {
    f->facs = animation_track(*read.animation, f->expression_au);
    f->facs_t_s = 0;
    f->mind.hold_expression(f->facs->length_s());
    what += " (expression sentence)";
  }
  if (read.emotion) {
    // On this face only, at the strengths the script wrote.
    f->vascular.start(*read.emotion, kRoomScriptEpisodeS, 1.0f);
    what += " (vascular " + read.emotion->name + ")";
  }
  for (const UnitDefinition& unit : read.units)
    what += " (AU " + std::to_string(unit.au) + (unit.restore ? " restored)" : " redefined)");
  impl_->event(face, std::move(what));
  return {};
}

// How long `text` takes to say without a speech track: by its words.
double estimated_speech_s(std::string_view text) {
  std::size_t words = 0;
  bool in_word = false;
  for (const char c : text) {
    const bool letter = std::isalnum(static_cast<unsigned char>(c)) != 0 || (c & 0x80) != 0;
    words += letter && !in_word ? 1 : 0;
    in_word = letter;
  }
  return std::clamp(static_cast<double>(words) / kWordsPerSecond, kShortestLineS, kLongestLineS);
}

void BehaviorRoom::chat(FaceId face, std::string_view text, const AuTrack* mouth) {
  Impl::Face* f = impl_->find(face);
  if (!f) return;
  const EmotionPoint delta = appraise_chat(text);
  f->emotion.nudge(delta);
  EmotionPoint share{};
  for (std::size_t k = 0; k < kPrimaryCount; ++k) share[k] = kRoomMoodShare * delta[k];
  impl_->room_mood = clamp_to_cube([&] {
    EmotionPoint sum = impl_->room_mood;
    for (std::size_t k = 0; k < kPrimaryCount; ++k) sum[k] += share[k];
    return sum;
  }());
  if (embarrassing_chat(text)) f->vascular.embarrass();
  const auto strongest = std::max_element(delta.begin(), delta.end());
  if (*strongest >= 0.3f)
    f->emotion.express(static_cast<Primary>(strongest - delta.begin()), envelope_for(2.0, *strongest, 0.5f));
  f->speech_start_s = impl_->now_s();
  f->speech_length_s = mouth ? mouth->length_s() : estimated_speech_s(text);
  if (mouth) f->speech_mouth = *mouth;
  else f->speech_mouth.reset();
  for (Impl::Face& other : impl_->faces)
    if (other.id != face && names(text, other.name)) other.mind.draw_attention(face, f->speech_length_s + kNamedAttentionAfterS);
  impl_->event(face, std::string("chat (") + label(classify(delta)) + ")");
}

bool BehaviorRoom::speaking(FaceId face) const { return impl_->get(face).speech_start_s.has_value(); }
const std::optional<AuTargets>& BehaviorRoom::articulation(FaceId face) const { return impl_->get(face).articulation; }

void BehaviorRoom::tick() { impl_->step(); }
std::uint32_t BehaviorRoom::tick_index() const { return impl_->tick; }
double BehaviorRoom::dt_s() const { return impl_->dt(); }
const codec::FaceParams& BehaviorRoom::face(FaceId id) const { return impl_->get(id).params; }
const FaceSnapshot& BehaviorRoom::snapshot(FaceId id) const { return impl_->get(id).snapshot; }
Routine BehaviorRoom::routine(FaceId id) const { return impl_->get(id).mind.routine(); }
std::optional<FaceId> BehaviorRoom::attending(FaceId id) const { return impl_->get(id).attending; }
EmotionPoint BehaviorRoom::mood(FaceId face) const { return impl_->get(face).emotion.mood(); }

void BehaviorRoom::set_mood(FaceId face, const EmotionPoint& mood) {
  if (Impl::Face* f = impl_->find(face)) {
    f->emotion.reset();
    f->emotion.nudge(mood);  // from rest, the nudge is the mood (both stay in the cube)
  }
}

bool BehaviorRoom::leader(FaceId id) const { return impl_->get(id).mind.leader(); }
Seat BehaviorRoom::seat(FaceId id) const { return impl_->get(id).snapshot.seat; }
YawPitch BehaviorRoom::gaze(FaceId id) const { return impl_->get(id).eyes.gaze(); }
int BehaviorRoom::blinks(FaceId id) const { return impl_->get(id).blink.count(); }

std::vector<BehaviorEvent> BehaviorRoom::take_events() { return std::exchange(impl_->events, {}); }

}  // namespace fw::behavior
