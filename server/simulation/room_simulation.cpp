#include "room_simulation.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <memory>
#include <type_traits>
#include <utility>

#include "fw/behavior/behavior_room.hpp"
#include "fw/behavior/articulation.hpp"
#include "fw/behavior/facs_track.hpp"
#include "fw/behavior/room_script.hpp"
#include "fw/behavior/plateau_motion.hpp"
#include "spoken_lines.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/avatar_tissue.hpp"
#include "fw/physics/face_pool.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/muscle_activation.hpp"
#include "fw/physics/muscle_variation.hpp"
#include "fw/physics/tissue_model.hpp"
#include "face_model.hpp"
#include "avatar_ids.hpp"
#include "face_overrides.hpp"
#include "preview_surface.hpp"
#include "script_check.hpp"
#include "redefined_units.hpp"
#include "redefinition_budget.hpp"

namespace fw::server {
namespace {
using AuTargets = std::array<float, codec::kAuChannelCount>;
using Correctives = std::array<float, codec::kCorrectiveCount>;
}  // namespace

// ---------------------------------------------------------------------------
// The physics face: the one place it is called.
//
// Behavior wants `targets` (action-unit intensities); the physics face turns
// them into muscle activations, steps the soft tissue by `dt_s`, and its
// measured surface, projected on the AU basis, is what the face shows, with
// what the AUs leave projected on the corrective components. A face
// at rest (muscles at their targets, nothing moving) is neither stepped nor
// measured again while its targets stay the same.
//
// Under load (RoomSimulation::set_physics_share) a face may instead follow
// its targets kinematically: each AU approaches its target with the muscles'
// activation time constants. That track is kept always (29 numbers), so a
// face that gets physics back blends from it into the physics output.
// Outside the anonymous namespace: RoomSimulation::State, which the header
// names, holds one per avatar.
struct PhysicsFace {
  std::unique_ptr<physics::FaceSimulation> simulation;
  physics::Solver solver = physics::Solver::mass_spring;  ///< the simulation's, when it is made
  /// The avatar's own face (face_model.hpp), null until it is built: the
  /// generic face meanwhile. `variation_seed` its muscles' (its asset id's).
  std::shared_ptr<const FaceModel> own;
  std::uint64_t variation_seed = 0;
  /// What the face showed last, and, after it took its own face, the share
  /// (0 .. 1) of the new face's output in what it shows (wear_face).
  AuTargets output{};
  Correctives output_corrective{};
  double own_blend = 1;
  AuTargets shown{};      ///< the physics face's last measurement
  Correctives corrective{};  ///< ... its corrective weights (0 with redefined units)
  AuTargets kinematic{};  ///< the targets followed without tissue
  double blend = 1;       ///< weight of the physics output: 0 .. 1
  double catching_up_s = 0;  ///< time the physics face has had to catch up since it came back
  bool resting = true;
};

namespace {

// A face that gets physics back shows its kinematic track until the tissue,
// stepped again from where it was left, is this close to it (or for at most
// kCatchUpS), and then blends over RoomSimulation::kPhysicsBlendS.
constexpr float kCloseEnough = 0.1f;
constexpr double kCatchUpS = 1.0;

// Under the codec's finest action-unit step (1/256).
constexpr float kKinematicRestGap = 1.0f / 512.0f;

// A face without tissue follows its targets as its muscles would (the
// physics face's own activation lag and time constants).
void follow_kinematically(PhysicsFace& face, const AuTargets& targets, double dt_s) {
  constexpr physics::SimulationOptions kMuscles{};
  const physics::ActivationRates rates =
      physics::activation_rates(kMuscles.activation_time_s, kMuscles.deactivation_time_s, static_cast<float>(dt_s));
  for (std::size_t c = 0; c < targets.size(); ++c)
    face.kinematic[c] = physics::follow_activation(face.kinematic[c], targets[c], rates);
}

// The tissue model a face simulates: its avatar's own once built, else the
// generic face's (shared by every face).
std::shared_ptr<const physics::TissueModel> tissue_of(const PhysicsFace& face) {
  return face.own ? face.own->tissue : physics::generic_tissue_model();
}

// The corrective components it is measured against, cloned onto the same
// face as its tissue model's AU basis.
std::shared_ptr<const physics::CorrectiveBasis> correctives_of(const PhysicsFace& face) {
  if (face.own) return face.own->correctives;
  static const auto generic = std::make_shared<const physics::CorrectiveBasis>(
      physics::CorrectiveBasis::from_morphs(model::generic_face().correctives, physics::generic_tissue_model()->basis));
  return generic;
}

// A preview's physics level (face_overrides.hpp): its muscles' floor, and
// its own tissue model when its skin is not normal() (the generic model is
// shared by every face: it is never changed, another is built).
// Building a tissue model takes about 7 ms (the generic face's, on one
// core): a skin slider dragged would ask for one every tick, so a preview
// rebuilds at most every kSkinRebuildS and takes the newest values then.
constexpr double kSkinRebuildS = 0.2;

void apply_physics_level(const PhysicsFace& face, physics::FaceSimulation& sim, const FaceOverrides& overrides,
                         std::pair<float, float>& applied_skin, double now_s, double& rebuilt_s) {
  static_assert(kOverrideMuscles == physics::kMuscleCount);
  if (overrides.muscles != sim.muscle_floor()) sim.set_muscle_floor(overrides.muscles);
  const std::pair<float, float> skin{overrides.skin_age, overrides.skin_looseness};
  if (skin == applied_skin || now_s - rebuilt_s < kSkinRebuildS) return;
  applied_skin = skin;
  rebuilt_s = now_s;
  if (skin == std::pair<float, float>{0.0f, 0.0f}) return sim.replace_model(tissue_of(face));
  physics::TissueOptions options;
  options.material = physics::TissueMaterial::aged(skin.first, skin.second);
  sim.replace_model(physics::build_avatar_tissue_model(face.own ? face.own->avatar : model::generic_avatar_model(),
                                                       nullptr, options));
}

// Whether every redefined unit's own track has reached its target.
bool redefined_at_rest(const PhysicsFace& face, const AuTargets& targets, const RedefinedUnits& units) {
  for (const auto& [channel, morph] : units.morphs())
    if (std::abs(targets[channel] - face.kinematic[channel]) >= kKinematicRestGap) return false;
  return true;
}

// A face with redefined units (redefined_units.hpp): the physics face makes
// the shipped ones, each redefined unit moves by its morph on its own track,
// and the face is measured against the avatar's own basis every tick. Its
// corrective weights are 0: the components were fitted to what the shipped
// basis leaves, and what the avatar's own basis leaves is another residual.
physics::FaceSimulation& simulation_of(PhysicsFace& face, std::uint64_t seed) {
  if (!face.simulation) {
    physics::SimulationOptions o;
    o.seed = face.variation_seed ? face.variation_seed : seed;
    o.individual_variation = physics::kPersonVariation;  // a person's muscles
    o.course_variation = physics::kPersonCourseVariation;
    o.solver = face.solver;
    face.simulation = std::make_unique<physics::FaceSimulation>(tissue_of(face), o, correctives_of(face));
  }
  return *face.simulation;
}

// A face's tick comes in two halves around the tissue's step, so that a
// server may step the faces of many rooms together (RoomSimulation::begin_tick).
//
// The first half: the kinematic track follows the targets, and a face on
// physics takes them as muscle targets (a redefined unit through its own
// track), and the head's pose, whose tilt and turns load its tissue.
// Returns whether its tissue needs a step.
bool prepare_step(PhysicsFace& face, const AuTargets& targets, const physics::HeadPose& head, double dt_s,
                  std::uint64_t seed, bool sleeps, bool physics_allowed, const RedefinedUnits& units) {
  follow_kinematically(face, targets, dt_s);
  if (!physics_allowed) return false;
  physics::FaceSimulation& sim = simulation_of(face, seed);
  sim.set_action_units(units.any() ? units.physics_targets(targets) : targets);
  sim.set_head_pose(head);
  return !sleeps || !sim.at_rest();
}

// The physics face's output after its step (`stepped`: it had one): its
// measurement, or the last one while it sleeps.
AuTargets measure_physics(PhysicsFace& face, const AuTargets& targets, bool sleeps, bool stepped,
                          const RedefinedUnits& units) {
  physics::FaceSimulation& sim = *face.simulation;
  if (units.any()) {
    units.measure(sim, face.kinematic, face.shown);
    face.corrective = {};
    face.resting = sleeps && sim.at_rest() && redefined_at_rest(face, targets, units);
    return face.shown;
  }
  if (stepped) {
    const physics::FaceMeasurement m = sim.measure();
    face.shown = m.action_units;
    face.corrective = m.corrective;
  }
  face.resting = sleeps && sim.at_rest();  // a face kept awake is stepped: it does not sleep
  return face.shown;
}

AuTargets physics_or_kinematic(PhysicsFace& face, const AuTargets& targets, double dt_s, bool sleeps,
                               bool physics_allowed, bool stepped, const RedefinedUnits& units,
                               Correctives& corrective);

// The second half of a face's action units, and after it took its own
// face (wear_face) what it showed going over to them in kOwnFaceBlendS: the
// same surface measured against other morphs gives other weights, and its
// muscles, laid on its own landmarks, hold it a little elsewhere (a smile
// on a face 10 % wider measures 0.2 to 0.4 less of AU 12); the tissue gets
// there within a few hundred milliseconds, which a second of blending
// spreads below a few hundredths of a unit a tick.
// `corrective` takes the corrective weights, blended the same ways.
AuTargets finish_action_units(PhysicsFace& face, const AuTargets& targets, double dt_s, bool sleeps,
                              bool physics_allowed, bool stepped, const RedefinedUnits& units,
                              Correctives& corrective) {
  AuTargets out = physics_or_kinematic(face, targets, dt_s, sleeps, physics_allowed, stepped, units, corrective);
  if (face.own_blend < 1) {
    face.own_blend = std::min(1.0, face.own_blend + dt_s / RoomSimulation::kOwnFaceBlendS);
    const auto mix = [w = face.own_blend](float now, float before) { return static_cast<float>(w * now + (1.0 - w) * before); };
    for (std::size_t c = 0; c < out.size(); ++c) out[c] = mix(out[c], face.output[c]);
    for (std::size_t k = 0; k < corrective.size(); ++k) corrective[k] = mix(corrective[k], face.output_corrective[k]);
    face.resting = false;
  }
  face.output = out;
  face.output_corrective = corrective;
  return out;
}

// Physics when it may, else kinematic, blending after a change from
// kinematic to physics. `corrective` takes the corrective weights: the
// physics face's, blended like the AUs (a kinematic face has none, so they
// fade in from 0).
AuTargets physics_or_kinematic(PhysicsFace& face, const AuTargets& targets, double dt_s, bool sleeps,
                               bool physics_allowed, bool stepped, const RedefinedUnits& units,
                               Correctives& corrective) {
  corrective = {};
  if (!physics_allowed) {
    face.blend = 0;
    face.catching_up_s = 0;
    // At rest once every unit is within a visible step of its target (an
    // exponential approach in floats need never land exactly).
    face.resting = true;
    for (std::size_t c = 0; c < targets.size(); ++c)
      face.resting = face.resting && std::abs(targets[c] - face.kinematic[c]) < kKinematicRestGap;
    return face.kinematic;
  }
  const AuTargets physical = measure_physics(face, targets, sleeps, stepped, units);
  if (face.blend >= 1) {
    corrective = face.corrective;
    return physical;
  }
  face.resting = false;  // still catching up or blending
  float gap = 0;
  for (std::size_t c = 0; c < physical.size(); ++c) gap = std::max(gap, std::abs(physical[c] - face.kinematic[c]));
  face.catching_up_s += dt_s;
  if (face.blend == 0 && gap > kCloseEnough && face.catching_up_s < kCatchUpS) return face.kinematic;
  face.blend = std::min(1.0, face.blend + dt_s / RoomSimulation::kPhysicsBlendS);
  for (std::size_t k = 0; k < corrective.size(); ++k)
    corrective[k] = static_cast<float>(face.blend * face.corrective[k]);
  AuTargets mixed;
  for (std::size_t c = 0; c < mixed.size(); ++c)
    mixed[c] = static_cast<float>(face.blend * physical[c] + (1.0 - face.blend) * face.kinematic[c]);
  return mixed;
}

// Where a face stands in the queue for physics under load: 0 .. 1, fixed.
double physics_rank(std::uint64_t key) {
  key += 0x9E3779B97F4A7C15ull;  // splitmix64
  key = (key ^ (key >> 30)) * 0xBF58476D1CE4E5B9ull;
  key = (key ^ (key >> 27)) * 0x94D049BB133111EBull;
  key ^= key >> 31;
  return static_cast<double>(key >> 11) * 0x1.0p-53;
}
// ---------------------------------------------------------------------------

}  // namespace

struct RoomSimulation::State {
  explicit State(const RoomSimulationOptions& o)
      : options(o), ids(o.id_space, o.id_quiet_ticks), room([&] {
          behavior::BehaviorRoomOptions b;
          b.seed = o.seed;
          b.tick_hz = o.tick_hz;
          b.seats = o.seats;
          return b;
        }()) {}

  /// A room's faces are solved by projective dynamics, a quarter of the
  /// cost; a preview, which shows one person the simulated skin itself, by
  /// the more exact mass-spring (a muscle no action unit has alone pulls the
  /// lip 8 times as far there: 1.44 against 0.18 in the lab's test).
  physics::Solver solver() const {
    return options.physics_projective && !options.preview ? physics::Solver::projective
                                                          : physics::Solver::mass_spring;
  }

  struct Avatar;
  /// A new avatar's state, its physics face to be solved by solver().
  void place(AvatarId id, const AvatarSetup& setup);

  struct Avatar {
    AvatarSetup setup;
    PhysicsFace physics;
    codec::FaceParams face;
    /// A preview's (options.preview): what its page set, and a FACS
    /// sentence played while its behaviour is off, with its time so far.
    FaceOverrides overrides = {};
    std::optional<behavior::AuTrack> played = {};
    double played_s = 0;
    /// Room time until which a script's vascular emotion colours the
    /// preview with its behaviour off (the episode's length).
    double scripted_colour_until_s = 0;
    RedefinedUnits units;  ///< its person's AU definitions
    /// A preview's: the weights its physics face gave the frame (before
    /// speech and plateau motion), and the skin (age, looseness) its tissue
    /// model was built with.
    AuTargets measured{};
    /// Between begin_tick and finish_tick: whether the face runs physics
    /// this tick, may sleep, and was handed out for its tissue's step.
    struct TickPhase {
      bool allowed = false, sleeps = false, stepped = false;
    } phase;
    std::pair<float, float> skin{0.0f, 0.0f};
    double skin_built_s = -1e9;  ///< room time its tissue model was last built
  };

  /// A preview's override; "" or why not.
  std::string preview_command(AvatarId id, const AvatarCommand& command);
  /// A preview plays an accepted script's expression sentence itself while
  /// its behaviour is off (the room's behaviour plays it too, for when the
  /// page turns behaviour on), and shows its vascular emotion's colour.
  void hold_sentence(AvatarId id, std::string_view script);
  RoomSimulationOptions options;
  AvatarIds ids;
  behavior::BehaviorRoom room;
  std::map<AvatarId, Avatar> avatars;
  std::vector<RoomEvent> events;
  SpokenLines lines;
  std::shared_ptr<TrackMaker> track_maker =
      options.track_maker ? options.track_maker : std::make_shared<ImmediateTrackMaker>();
  /// Whether this simulation still exists: a track handed back late (by a
  /// pooled maker, after the room moved or closed) checks it first.
  std::shared_ptr<bool> alive = std::make_shared<bool>(true);
  double physics_share = 1;
  bool mid_tick = false;  ///< begin_tick handed faces out; finish_tick not yet called
  /// Lines whose tracks came back mid-tick: they start after finish_tick,
  /// as if they had come just after the tick.
  std::vector<std::pair<LineJob, LineToSay>> held_lines;
  std::size_t physics_faces = 0, kinematic_faces = 0;
  RedefinitionBudget redefinitions;  ///< the bytes of unit morphs its people may send everyone

  /// The line of `job` starts, its track made (say_waiting_lines).
  void say_line(const LineJob& job, LineToSay line);

  // Events of a tick carry that tick's index; those of calls between ticks
  // the index of the tick they first act on.
  void collect_events(bool from_tick = false) {
    const std::uint32_t at = room.tick_index() - (from_tick ? 1 : 0);
    for (behavior::BehaviorEvent& e : room.take_events()) events.push_back({at, e.face, std::move(e.what)});
  }
};

RoomSimulation::RoomSimulation(const RoomSimulationOptions& options) : state_(std::make_unique<State>(options)) {}
RoomSimulation::~RoomSimulation() = default;
RoomSimulation::RoomSimulation(RoomSimulation&&) noexcept = default;
RoomSimulation& RoomSimulation::operator=(RoomSimulation&&) noexcept = default;

void RoomSimulation::State::say_line(const LineJob& job, LineToSay line) {
  State& s = *this;
  if (!s.lines.made(job.avatar, job.ticket) || !s.room.contains(job.avatar)) return;
  behavior::AuTrack mouth;
  mouth.times_s.reserve(line.mouth.size());
  for (std::size_t i = 0; i < line.mouth.size(); ++i)
    mouth.times_s.push_back(static_cast<double>(i) * LineToSay::kPoseStepS);
  mouth.poses.assign(line.mouth.begin(), line.mouth.end());
  s.room.chat(job.avatar, line.text, line.mouth.empty() ? nullptr : &mouth);
  if (!line.note.empty())
    s.events.push_back({s.room.tick_index(), job.avatar, "speech: " + line.note, "your line was " + line.note});
  // The room's events of a line said (chat, blush) before the tick's own.
  s.collect_events();
  if (!line.mouth.empty() && line.said_bytes > 0) {
    // The track starts with the next tick, whose frame carries its first pose.
    const double length_ms = mouth.times_s.back() * 1000.0;
    RoomEvent::LineBegun begun{
        s.room.tick_index() + 1,
        static_cast<std::uint32_t>(std::clamp(std::lround(length_ms), 0L, static_cast<long>(codec::kMaxSpeakingMs))),
        line.language, line.text.substr(0, line.said_bytes)};
    s.events.push_back({s.room.tick_index(), job.avatar, "speech: a line begins", "", std::move(begun)});
  }
  // A line that came back at once (ImmediateTrackMaker) or between ticks
  // leaves the avatar speaking; its next line waits for the end of this one.
}

void RoomSimulation::State::place(AvatarId id, const AvatarSetup& setup) {
  Avatar& avatar = avatars[id] = Avatar{};
  avatar.setup = setup;
  avatar.physics.solver = solver();
  avatar.physics.own = setup.face;
  if (!setup.asset.empty()) avatar.physics.variation_seed = physics::variation_seed(setup.asset);
}

bool RoomSimulation::wears_own_face(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  return it != state_->avatars.end() && it->second.physics.own != nullptr;
}

void RoomSimulation::wear_face(AvatarId avatar, std::shared_ptr<const FaceModel> face) {
  const auto it = state_->avatars.find(avatar);
  if (it == state_->avatars.end() || !face || it->second.physics.own == face) return;
  State::Avatar& a = it->second;
  a.setup.face = face;
  PhysicsFace& p = a.physics;
  p.own = std::move(face);
  if (!p.simulation) return;  // made with it at its first tick
  // The tissue goes on from where it is on the new face (replace_model
  // keeps each node's displacement), but its weights are measured against
  // the avatar's own morphs from now on: what it shows goes over to them
  // from what it showed (step_action_units).
  p.simulation->replace_model(tissue_of(p));
  p.simulation->set_correctives(correctives_of(p));
  p.own_blend = 0;
  if (state_->options.preview) a.skin = {-1.0f, -1.0f}, a.skin_built_s = -1e9;  // its skin again, on this face
}

AvatarId RoomSimulation::add_avatar(const AvatarSetup& setup) {
  State& s = *state_;
  const AvatarId id = s.ids.take(s.room.tick_index());
  if (id == 0) return 0;  // every id in use or resting
  if (!s.room.add(id, setup.name)) {
    s.ids.cancel(id);  // the room is full
    return 0;
  }
  s.place(id, setup);
  s.collect_events();
  return id;
}

bool RoomSimulation::restore_avatar(AvatarId id, const AvatarSetup& setup) {
  State& s = *state_;
  if (!s.ids.claim(id)) return false;
  if (!s.room.add(id, setup.name)) {
    s.ids.cancel(id);
    return false;
  }
  s.place(id, setup);
  s.collect_events();
  return true;
}

void RoomSimulation::set_language(AvatarId avatar, std::string language) {
  const auto it = state_->avatars.find(avatar);
  if (it != state_->avatars.end()) it->second.setup.language = std::move(language);
}

std::vector<float> RoomSimulation::mood(AvatarId avatar) const {
  if (!state_->room.contains(avatar)) return {};
  const behavior::EmotionPoint point = state_->room.mood(avatar);
  return {point.begin(), point.end()};
}

void RoomSimulation::set_mood(AvatarId avatar, const std::vector<float>& mood) {
  behavior::EmotionPoint point{};
  if (mood.size() != point.size() || !state_->room.contains(avatar)) return;
  std::copy(mood.begin(), mood.end(), point.begin());
  state_->room.set_mood(avatar, behavior::clamp_to_cube(point));
}

bool RoomSimulation::has_free_id() const {
  State& s = *state_;
  return s.ids.in_use() + s.ids.resting(s.room.tick_index()) + 1 < s.ids.space();
}

void RoomSimulation::remove_avatar(AvatarId avatar) {
  if (state_->avatars.erase(avatar) == 0) return;
  state_->room.remove(avatar);
  state_->lines.forget(avatar);
  state_->ids.give_back(avatar, state_->room.tick_index());
  state_->collect_events();
}

std::vector<AvatarId> RoomSimulation::avatars() const { return state_->room.faces(); }

std::string RoomSimulation::State::preview_command(AvatarId id, const AvatarCommand& command) {
  const auto it = avatars.find(id);
  if (it == avatars.end()) return "you are not in this room";
  return set_override(it->second.overrides, std::get<OverrideCommand>(command).change);
}

void RoomSimulation::State::hold_sentence(AvatarId id, std::string_view script) {
  const auto it = avatars.find(id);
  if (it == avatars.end()) return;
  behavior::RoomScript read;
  if (!behavior::read_room_script(script, read).empty()) return;
  if (read.emotion)
    it->second.scripted_colour_until_s = room.tick_index() * room.dt_s() + behavior::kRoomScriptEpisodeS;
  behavior::AuTrack track;
  std::string no_sentence;  // a script of definitions or a vascular emotion alone: nothing to hold
  if (!behavior::facs_track(script, track, no_sentence)) return;
  it->second.played = std::move(track);
  it->second.played_s = 0;
}

std::string RoomSimulation::command(AvatarId avatar, const AvatarCommand& command) {
  if (const auto* check = std::get_if<CheckCommand>(&command)) return check_script(check->script);
  if (std::holds_alternative<OverrideCommand>(command))
    return state_->options.preview
               ? state_->preview_command(avatar, command)
               : "overrides are for a face-lab preview (lab.html); in a room, use express or a FACS sentence";
  if (const auto* facs = std::get_if<FacsCommand>(&command)) {
    std::string result = script(avatar, facs->sentence);
    if (result.empty() && state_->options.preview) state_->hold_sentence(avatar, facs->sentence);
    return result;
  }
  behavior::BehaviorRoom& room = state_->room;
  std::string result = std::visit(
      [&](const auto& c) -> std::string {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, ExpressCommand>) return room.express(avatar, c.emotion, c.intensity, c.seconds);
        else if constexpr (std::is_same_v<T, LookAtCommand>) return room.look_at(avatar, c.target, c.seconds);
        else if constexpr (std::is_same_v<T, SnubCommand>) return room.snub(avatar, c.target, c.seconds);
        else return "a command this room does not take";  // overrides, checks and scripts are answered above
      },
      command);
  state_->collect_events();
  return result;
}

std::string RoomSimulation::script(AvatarId avatar, std::string_view text) {
  State& s = *state_;
  const auto it = s.avatars.find(avatar);
  if (it == s.avatars.end()) return "no avatar " + std::to_string(avatar) + " in this room";
  behavior::RoomScript read;
  if (std::string error = behavior::read_room_script(text, read); !error.empty()) return error;
  // The definitions are held to the avatar's bound before anything plays:
  // a script is taken whole or not at all.
  RedefinedUnits units = it->second.units;
  if (!read.units.empty()) {
    if (std::string error = units.apply(read.units); !error.empty()) return error;
    // Every client in the room receives the new set: the room's budget for
    // them (redefinition_budget.hpp) pays for its bytes.
    std::vector<std::uint8_t> set;
    codec::write_message(units.message(avatar), set);
    if (const auto wait = s.redefinitions.take(set.size(), s.room.tick_index() * s.room.dt_s()))
      return "this room's people redefined units faster than its links carry them (" +
             std::to_string(static_cast<int>(RedefinitionBudget::kBytesPerSecond)) +
             " bytes a second for all): try again in " + std::to_string(static_cast<int>(std::ceil(*wait))) + " s";
  }
  std::string result = s.room.facs(avatar, read);
  if (result.empty() && !read.units.empty()) it->second.units = std::move(units);
  s.collect_events();
  return result;
}

std::optional<codec::PreviewSurface> RoomSimulation::preview_surface(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  if (!state_->options.preview || it == state_->avatars.end() || !it->second.physics.simulation) return std::nullopt;
  const State::Avatar& a = it->second;
  return server::preview_surface(avatar, *a.physics.simulation, a.measured, a.units, a.physics.kinematic);
}

std::optional<codec::UnitMorphs> RoomSimulation::unit_morphs(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  if (it == state_->avatars.end() || it->second.units.version() == 0) return std::nullopt;
  return it->second.units.message(avatar);
}

std::string RoomSimulation::restore_unit_morphs(AvatarId avatar, const codec::UnitMorphs& set) {
  const auto it = state_->avatars.find(avatar);
  if (it == state_->avatars.end()) return "no avatar " + std::to_string(avatar) + " in this room";
  return it->second.units.restore(set);
}

void RoomSimulation::chat(AvatarId avatar, std::string_view text) {
  State& s = *state_;
  if (!s.room.contains(avatar)) return;
  const std::string& language = s.avatars.at(avatar).setup.language;
  if (!s.lines.add(avatar, std::string(text), language.empty() ? s.options.speech_language : language))
    s.events.push_back({s.room.tick_index(), avatar,
                        "speech: a line not said (" + std::to_string(SpokenLines::kMaxWaiting) + " lines wait)",
                        "your line is shown but not said: " + std::to_string(SpokenLines::kMaxWaiting) +
                            " of your lines are still waiting to be said"});
  say_waiting_lines();
}

void RoomSimulation::say_waiting_lines() {
  State& s = *state_;
  for (const AvatarId avatar : s.lines.with_lines()) {
    std::optional<LineJob> job = s.lines.next(avatar, s.room.speaking(avatar));
    if (!job) continue;
    const std::uint64_t ticket = job->ticket;
    // A maker that hands the line back later does so on the room's strand,
    // where the simulation's state is checked to be there still (alive).
    const bool taken = s.track_maker->make(
        std::move(*job), [state = &s, alive = std::weak_ptr<bool>(s.alive)](LineJob made, LineToSay line) {
          if (alive.expired()) return;
          if (state->mid_tick) state->held_lines.emplace_back(std::move(made), std::move(line));
          else state->say_line(made, std::move(line));
        });
    if (taken) continue;
    s.lines.made(avatar, ticket);
    s.events.push_back({s.room.tick_index(), avatar, "speech: a line not said (the speech worker is full)",
                        "your line is shown but not said: the server is busy saying other lines; try again soon"});
  }
}

bool RoomSimulation::speaking(AvatarId avatar) const {
  return state_->room.contains(avatar) && state_->room.speaking(avatar);
}

void RoomSimulation::tick() {
  TickFaces out = begin_tick();
  // A room alone steps its own faces together (batched as the pool would).
  physics::step_together(out.faces, out.dt_s);
  finish_tick();
}

RoomSimulation::TickFaces RoomSimulation::begin_tick() {
  State& s = *state_;
  assert(!s.mid_tick);
  say_waiting_lines();
  s.room.tick();
  s.physics_faces = s.kinematic_faces = 0;
  const double now_s = s.room.tick_index() * s.room.dt_s();
  TickFaces out;
  out.dt_s = s.room.dt_s();
  for (auto& [id, a] : s.avatars) {
    a.face = s.room.face(id);
    if (s.options.preview) {
      // Before the physics face, as a room's behaviour targets are.
      std::optional<behavior::AuTargets> played;
      if (a.played && !a.overrides.behaviour) {
        a.played_s += s.room.dt_s();
        played = a.played->at(a.played_s);
        if (a.played_s >= a.played->length_s()) a.played.reset();
      } else {
        a.played.reset();  // with behaviour on, the behaviour plays it
      }
      apply_overrides(a.overrides, a.face, played ? &*played : nullptr, now_s < a.scripted_colour_until_s);
    }
    // While a line is said its track owns the jaw and lips (laid over the
    // face in finish_tick); the tissue and the kinematic track hold the
    // rest of the face (articulation.hpp, without_articulation).
    if (s.room.articulation(id)) a.face.au = behavior::without_articulation(a.face.au);
    a.phase = {};
    if (!s.options.physics) continue;
    const std::uint64_t seed = s.options.seed ^ id;
    // A preview's page shows the physics face itself (its muscles, its
    // skin): it keeps physics under load, and never sleeps while a
    // muscle is driven from its page.
    a.phase.allowed = s.options.preview || s.physics_share >= 1.0 || physics_rank(seed) < s.physics_share;
    a.phase.sleeps = s.options.physics_sleeps;
    if (s.options.preview) {
      apply_physics_level(a.physics, simulation_of(a.physics, seed), a.overrides, a.skin, now_s, a.skin_built_s);
      a.phase.sleeps = a.phase.sleeps && !a.overrides.any_muscle();
    }
    a.phase.stepped = prepare_step(a.physics, a.face.au, model::head_pose(a.face), s.room.dt_s(), seed, a.phase.sleeps,
                                   a.phase.allowed, a.units);
    if (a.phase.stepped) out.faces.push_back(a.physics.simulation.get());
    ++(a.phase.allowed ? s.physics_faces : s.kinematic_faces);
  }
  // From here to finish_tick a line whose track comes back waits (a line
  // made at once above starts in this tick's frame).
  s.mid_tick = true;
  return out;
}

void RoomSimulation::finish_tick() {
  State& s = *state_;
  assert(s.mid_tick);
  s.mid_tick = false;
  const double now_s = s.room.tick_index() * s.room.dt_s();
  for (auto& [id, a] : s.avatars) {
    const std::uint64_t seed = s.options.seed ^ id;
    if (!s.options.physics) {
      a.physics.resting = true;  // no physics face to step
    } else {
      a.face.au = finish_action_units(a.physics, a.face.au, s.room.dt_s(), a.phase.sleeps, a.phase.allowed,
                                      a.phase.stepped, a.units, a.face.corrective);
      a.measured = a.face.au;
      // A preview's frames carry its whole residual in its preview surface
      // (preview_surface.hpp, what the AUs do not rebuild): corrective
      // weights on top would count it twice.
      if (s.options.preview) a.face.corrective = {};
    }
    // Speech moves jaw and lips at syllable rate (4-5 a second); the
    // tissue's response would smooth that to half, so the track's
    // articulation is shown as it is, over a face whose tissue was not
    // given it (begin_tick).
    if (const auto& mouth = s.room.articulation(id)) behavior::articulate(a.face.au, *mouth);
    // After the physics face, so that its tissue may rest on a held
    // expression while the expression still wavers (plateau_motion.hpp).
    behavior::add_plateau_motion(a.face.au, now_s, static_cast<std::uint32_t>(seed));
  }
  s.collect_events(true);
  for (auto& [job, line] : std::exchange(s.held_lines, {})) s.say_line(job, std::move(line));
}

void RoomSimulation::set_physics_share(double share) { state_->physics_share = std::clamp(share, 0.0, 1.0); }

std::size_t RoomSimulation::physics_faces() const { return state_->physics_faces; }
std::size_t RoomSimulation::kinematic_faces() const { return state_->kinematic_faces; }

std::uint32_t RoomSimulation::tick_index() const { return state_->room.tick_index(); }

const codec::FaceParams& RoomSimulation::face(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  assert(it != state_->avatars.end());
  return it->second.face;
}

codec::SeatInfo RoomSimulation::seat(AvatarId avatar) const {
  const behavior::Seat seat = state_->room.seat(avatar);
  return {seat.origin_mm.x, seat.origin_mm.y, seat.origin_mm.z, seat.facing_yaw_rad};
}

codec::Attention::Entry RoomSimulation::attention(AvatarId avatar) const {
  const behavior::BehaviorRoom& room = state_->room;
  if (const auto target = room.attending(avatar)) return {avatar, codec::AttentionTarget::avatar, *target};
  if (room.routine(avatar) == behavior::Routine::snubbing) return {avatar, codec::AttentionTarget::nobody, 0};
  return {avatar, codec::AttentionTarget::room, 0};
}

bool RoomSimulation::resting(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  return it != state_->avatars.end() && it->second.physics.resting;
}

std::vector<RoomEvent> RoomSimulation::take_events() { return std::exchange(state_->events, {}); }

}  // namespace fw::server
