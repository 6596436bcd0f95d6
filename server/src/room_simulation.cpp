#include "room_simulation.hpp"

#include <cassert>
#include <map>
#include <memory>
#include <type_traits>
#include <utility>

#include "fw/behavior/behavior_room.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/physics/tissue_model.hpp"

namespace fw::server {
namespace {

using AuTargets = std::array<float, codec::kAuChannelCount>;

// ---------------------------------------------------------------------------
// The physics face: the one place it is called.
//
// Behavior wants `targets` (action-unit intensities); the physics face turns
// them into muscle activations, steps the soft tissue by `dt_s`, and its
// measured surface, projected on the AU basis, is what the face shows. A face
// at rest (muscles at their targets, nothing moving) is neither stepped nor
// measured again while its targets stay the same.
struct PhysicsFace {
  std::unique_ptr<physics::FaceSimulation> simulation;
  AuTargets shown{};
  bool resting = true;
};

// Every avatar is drawn as the generic face, so they share its tissue model.
std::shared_ptr<const physics::TissueModel> generic_tissue() {
  static const std::shared_ptr<const physics::TissueModel> tissue =
      physics::build_tissue_model(model::generic_face(), model::generic_face().action_units);
  return tissue;
}

AuTargets step_physics(PhysicsFace& face, const AuTargets& targets, double dt_s, std::uint64_t seed,
                       const RoomSimulationOptions& options) {
  if (!face.simulation) {
    physics::SimulationOptions o;
    o.seed = seed;
    face.simulation = std::make_unique<physics::FaceSimulation>(generic_tissue(), o);
  }
  physics::FaceSimulation& sim = *face.simulation;
  sim.set_action_units(targets);
  if (!options.physics_sleeps || !sim.at_rest()) {
    sim.step(dt_s);
    face.shown = sim.measure().action_units;
  }
  face.resting = sim.at_rest();
  return face.shown;
}
// ---------------------------------------------------------------------------

}  // namespace

struct RoomSimulation::State {
  explicit State(const RoomSimulationOptions& o)
      : options(o), room([&] {
          behavior::BehaviorRoomOptions b;
          b.seed = o.seed;
          b.tick_hz = o.tick_hz;
          b.seats = o.seats;
          return b;
        }()) {}

  struct Avatar {
    AvatarSetup setup;
    PhysicsFace physics;
    codec::FaceParams face;
  };
  RoomSimulationOptions options;
  behavior::BehaviorRoom room;
  std::map<AvatarId, Avatar> avatars;
  AvatarId next_id = 1;
  std::vector<RoomEvent> events;

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

AvatarId RoomSimulation::add_avatar(const AvatarSetup& setup) {
  State& s = *state_;
  const AvatarId id = s.next_id;
  if (!s.room.add(id, setup.name)) return 0;  // the room is full
  ++s.next_id;
  s.avatars[id] = {setup, {}, {}};
  s.collect_events();
  return id;
}

void RoomSimulation::remove_avatar(AvatarId avatar) {
  state_->room.remove(avatar);
  state_->avatars.erase(avatar);
  state_->collect_events();
}

std::vector<AvatarId> RoomSimulation::avatars() const { return state_->room.faces(); }

std::string RoomSimulation::command(AvatarId avatar, const AvatarCommand& command) {
  behavior::BehaviorRoom& room = state_->room;
  std::string result = std::visit(
      [&](const auto& c) -> std::string {
        using T = std::decay_t<decltype(c)>;
        if constexpr (std::is_same_v<T, ExpressCommand>) return room.express(avatar, c.emotion, c.intensity, c.seconds);
        else if constexpr (std::is_same_v<T, LookAtCommand>) return room.look_at(avatar, c.target, c.seconds);
        else if constexpr (std::is_same_v<T, SnubCommand>) return room.snub(avatar, c.target, c.seconds);
        else return room.facs(avatar, c.sentence);
      },
      command);
  state_->collect_events();
  return result;
}

void RoomSimulation::chat(AvatarId avatar, std::string_view text) {
  state_->room.chat(avatar, text);
  state_->collect_events();
}

void RoomSimulation::tick() {
  State& s = *state_;
  s.room.tick();
  for (auto& [id, a] : s.avatars) {
    a.face = s.room.face(id);
    if (s.options.physics) a.face.au = step_physics(a.physics, a.face.au, s.room.dt_s(), s.options.seed ^ id, s.options);
    else a.physics.resting = true;  // no physics face to step
  }
  s.collect_events(true);
}

std::uint32_t RoomSimulation::tick_index() const { return state_->room.tick_index(); }

const codec::FaceParams& RoomSimulation::face(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  assert(it != state_->avatars.end());
  return it->second.face;
}

bool RoomSimulation::resting(AvatarId avatar) const {
  const auto it = state_->avatars.find(avatar);
  return it != state_->avatars.end() && it->second.physics.resting;
}

std::vector<RoomEvent> RoomSimulation::take_events() { return std::exchange(state_->events, {}); }

}  // namespace fw::server
