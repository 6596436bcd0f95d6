#include "room.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

#include "bridged_room.hpp"
#include "delivery_batch.hpp"
#include "owned_room.hpp"
#include "room_registry.hpp"

namespace fw::server {

namespace net = boost::asio;

namespace {

// Ticks start on a grid of kTickPhases a period, shared by every room: the
// rooms of one phase tick together and hand their faces to the stepper
// together (fuller batches), while the phases spread the rooms' work over
// the period. The first point of the grid at or after `t`.
constexpr int kTickPhases = 8;
std::chrono::steady_clock::time_point on_phase_grid(std::chrono::steady_clock::time_point t,
                                                    std::chrono::microseconds period) {
  const std::chrono::nanoseconds phase = period / kTickPhases;
  const std::chrono::nanoseconds since = t.time_since_epoch();
  return std::chrono::steady_clock::time_point((since + phase - std::chrono::nanoseconds(1)) / phase * phase);
}

RoomSimulationOptions simulation_options(const ServerConfig& config, std::uint64_t seed,
                                         std::shared_ptr<TrackMaker> track_maker, bool preview) {
  RoomSimulationOptions options{seed, config.tick_hz, config.physics, config.physics_sleeps};
  options.preview = preview;
  options.physics_projective = config.physics_projective;
  options.track_maker = std::move(track_maker);
  options.id_space = config.avatar_id_space;
  // Ticks never run ahead of the clock, so this many of them last at least as long.
  options.id_quiet_ticks =
      static_cast<std::uint64_t>((config.avatar_id_quiet.count() * config.tick_hz + 999) / 1000);
  return options;
}

std::unique_ptr<RoomRole> make_role(Room& room, RoomRoleKind kind) {
  switch (kind) {
    case RoomRoleKind::bridge: return std::make_unique<BridgedRoom>(room);
    case RoomRoleKind::owner: break;
  }
  return std::make_unique<OwnedRoom>(room);
}

}  // namespace

Room::Room(const RoomServices& services, RoomRegistry& registry, std::string name, bool persistent,
           std::uint64_t seed, RoomRoleKind role, bool preview)
    : services_(services), registry_(registry), name_(std::move(name)), persistent_(persistent), preview_(preview),
      strand_(net::make_strand(services.workers)), timer_(strand_),
      track_maker_(std::make_shared<RoomTrackMaker>(services.speech, strand_, services.metrics.unsaid_lines)),
      simulation_(simulation_options(services.config, seed, track_maker_, preview)), role_(make_role(*this, role)),
      kind_(role) {
  services_.metrics.rooms.fetch_add(1);
}

Room::~Room() {
  role_.reset();  // before the simulation and the counts it uses
  services_.metrics.rooms.fetch_sub(1);
  services_.metrics.kinematic_faces.fetch_sub(static_cast<std::int64_t>(counts_.kinematic_faces));
  services_.metrics.avatars.fetch_sub(static_cast<std::int64_t>(counts_.avatars.load()));
}

template <class Work>
void Room::on_strand(Work work) {
  // Shared, so that a request held while a tick's faces are out can wait
  // in a std::function whatever it captured.
  net::post(strand_, [self = shared_from_this(), work = std::make_shared<Work>(std::move(work))] {
    if (self->ticking_) self->held_.push_back([work] { (*work)(); });
    else (*work)();
  });
}

template <class Work>
void Room::post_open(Work work) {
  on_strand([self = shared_from_this(), work = std::move(work)]() mutable {
    if (!self->closed_) work(*self->role_);
  });
}

void Room::start() {
  // Tracks handed back after the room is gone are dropped (speech_worker.hpp).
  track_maker_->bind(weak_from_this());
  net::post(strand_, [self = shared_from_this()] {
    self->next_tick_ = on_phase_grid(std::chrono::steady_clock::now(), self->tick_period());
    self->schedule_tick();
  });
}

void Room::close() {
  on_strand([self = shared_from_this()] {
    self->closed_ = true;
    self->timer_.cancel();
    self->role_->close();
  });
}

bool Room::unpeopled() const { return role_->unpeopled(); }

void Room::then(std::function<void()> done) {
  on_strand([done = std::move(done)] { done(); });
}

void Room::wear_face(std::uint32_t avatar, std::string version, std::shared_ptr<const FaceModel> face) {
  post_open([avatar, version = std::move(version), face = std::move(face)](RoomRole& role) mutable {
    role.wear_face(avatar, version, std::move(face));
  });
}

void Room::join(JoinRequest request) {
  counts_.pending_joins.fetch_add(1);
  on_strand([self = shared_from_this(), request = std::move(request)]() mutable {
    self->do_join(std::move(request));
  });
}

void Room::do_join(JoinRequest request) {
  counts_.pending_joins.fetch_sub(1);
  if (closed_) return join_successor(std::move(request));
  role_->join(std::move(request));
}

void Room::join_successor(JoinRequest request) {
  if (!request.connection) return;
  // A preview is nobody's to open again by name: its page asks for a new one.
  if (preview_)
    return request.connection->close(codec::CloseCode::normal, "the face-lab preview ended; reload the page");
  if (auto room = registry_.find_or_create(name_)) return room->join(std::move(request));
  if (services_.draining.load())
    request.connection->close(codec::CloseCode::shutting_down, "the server is shutting down; try again soon");
  else
    request.connection->close(codec::CloseCode::server_full, "the server holds its maximum number of rooms");
}

void Room::leave(std::uint32_t avatar) {
  post_open([avatar](RoomRole& role) { role.leave(avatar); });
}

void Room::chat(std::uint32_t avatar, std::string text) {
  post_open([avatar, text = std::move(text)](RoomRole& role) mutable { role.chat(avatar, std::move(text)); });
}

void Room::command(std::uint32_t avatar, codec::Command command) {
  post_open([avatar, command = std::move(command)](RoomRole& role) { role.command(avatar, command); });
}

void Room::resync(std::uint32_t avatar, std::vector<std::uint32_t> avatars) {
  post_open([avatar, avatars = std::move(avatars)](RoomRole& role) { role.resync(avatar, avatars); });
}

void Room::set_rate(std::uint32_t avatar, std::uint32_t bps) {
  post_open([avatar, bps](RoomRole& role) { role.set_rate(avatar, bps); });
}

void Room::replace_deleted_avatar(std::string asset) {
  if (services_.procedural_faces.empty()) return;
  post_open([asset = std::move(asset)](RoomRole& role) { role.replace_deleted_avatar(asset); });
}

void Room::on_up(bridge::Up message) {
  post_open([message = std::move(message)](RoomRole& role) mutable { role.on_up(message); });
}

void Room::on_down(bridge::Down message) {
  post_open([message = std::move(message)](RoomRole& role) mutable { role.on_down(message); });
}

void Room::node_gone(std::string node) {
  post_open([node = std::move(node)](RoomRole& role) { role.node_gone(node); });
}

void Room::node_back(std::string node) {
  post_open([node = std::move(node)](RoomRole& role) { role.node_back(node); });
}

void Room::keep_all() {
  post_open([](RoomRole& role) { role.keep_all(); });
}

void Room::ask_roster() {
  post_open([](RoomRole& role) { role.ask_roster(); });
}

void Room::take_over(std::vector<bridge::MemberRecord> members, std::optional<bridge::RoomState> state,
                     std::set<std::string> live_nodes) {
  on_strand([self = shared_from_this(), members = std::move(members), state = std::move(state),
             live_nodes = std::move(live_nodes)]() mutable {
    if (self->closed_) return;
    RoomHandover handover = self->role_->hand_over();
    auto owner = std::make_unique<OwnedRoom>(*self);
    OwnedRoom& owned = *owner;
    self->role_ = std::move(owner);
    self->kind_ = RoomRoleKind::owner;
    owned.restore(std::move(members), std::move(state), live_nodes, std::move(handover.members));
    // What waited for the old owner is this node's to seat now.
    for (JoinRequest& request : handover.waiting_joins) {
      self->counts_.pending_joins.fetch_add(1);
      self->do_join(std::move(request));
    }
  });
}

void Room::step_down() {
  on_strand([self = shared_from_this()] {
    if (self->closed_ || self->kind_ != RoomRoleKind::owner) return;
    self->role_->step_down();
    self->role_ = std::make_unique<BridgedRoom>(*self);
    self->kind_ = RoomRoleKind::bridge;
  });
}

void Room::close_if_unpeopled() {
  if (persistent_ || !role_->unpeopled() || counts_.pending_joins.load() != 0 || role_->awaiting_joins()) return;
  services_.bus.room_closed(name_);
  registry_.remove_if_empty(shared_from_this());
}

std::chrono::microseconds Room::tick_period() const {
  return std::chrono::microseconds(1'000'000 / services_.config.tick_hz);
}

void Room::schedule_tick() {
  const auto period = tick_period();
  next_tick_ += period;
  const auto now = std::chrono::steady_clock::now();
  if (next_tick_ < now - period) {
    // More than a tick behind (an overloaded pool): keep the pace from now
    // instead of running a burst of ticks to catch up.
    services_.metrics.late_ticks.fetch_add(1, std::memory_order_relaxed);
    next_tick_ = on_phase_grid(now, period);
  }
  timer_.expires_at(next_tick_);
  timer_.async_wait([self = shared_from_this()](const boost::system::error_code& ec) {
    if (ec || self->closed_) return;
    self->run_tick();
  });
}

void Room::run_tick() {
  ticking_ = true;
  RoomSimulation::TickFaces faces = role_->begin_tick(next_tick_);
  if (faces.faces.empty()) return end_tick();
  // Dispatched: when this worker stepped the faces itself (FaceStepper), the
  // tick ends at once, still on the strand; else it is queued there.
  services_.face_stepper.step(std::move(faces.faces), faces.dt_s, [self = shared_from_this()] {
    net::dispatch(self->strand_, [self] { self->end_tick(); });
  });
}

void Room::end_tick() {
  // The tick's messages reach the I/O threads in one post, not one per subscriber.
  const DeliveryBatch batch;
  role_->finish_tick();
  ticking_ = false;
  // What came meanwhile, in the order it came (a close among it stops the ticks).
  for (auto& work : std::exchange(held_, {})) work();
  if (!closed_) schedule_tick();
}

}  // namespace fw::server
