#pragma once
// One room as sessions and the registry see it: its name, its strand on the
// worker pool, its tick timer and its simulation, and the role it plays on
// this node (room_role.hpp): the owner, which simulates it (owned_room.hpp),
// or a bridge to its owner on another node (bridged_room.hpp). Every
// request is posted to the room's strand, never run in an I/O handler, and
// handed to the role there.
//
// The role can change while the room runs: a bridge whose owner died takes
// the room over, an owner that lost its lease steps down. Room stays the
// same object (sessions hold it) and puts a new role in place of the old,
// which hands over the people connected here (RoomHandover).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>

#include "bridge_message.hpp"
#include "fw/codec/messages.hpp"
#include "join_request.hpp"
#include "room_bus.hpp"
#include "room_services.hpp"
#include "room_simulation.hpp"

namespace fw::server {

class RoomRegistry;
class RoomRole;

/// What a room counts for the registry and /metrics, read from any thread.
struct RoomCounts {
  std::atomic<std::size_t> avatars{0};
  std::atomic<std::size_t> persons{0};        ///< everyone's, bridged and away too
  std::atomic<std::size_t> local_persons{0};  ///< people connected to this node
  std::atomic<int> pending_joins{0};          ///< joins posted and not yet done
  std::size_t kinematic_faces = 0;  ///< the room's share of Metrics::kinematic_faces (on its strand)
};

class Room : public std::enable_shared_from_this<Room> {
 public:
  /// A room of `registry` (which closes it when nobody keeps it open),
  /// starting in `role`; a face-lab `preview` simulates its avatar under
  /// the person's overrides (RoomSimulationOptions::preview).
  Room(const RoomServices& services, RoomRegistry& registry, std::string name, bool persistent, std::uint64_t seed,
       RoomRoleKind role, bool preview = false);
  ~Room();

  const std::string& name() const { return name_; }
  bool persistent() const { return persistent_; }
  /// A face-lab preview (RoomRegistry::open_preview).
  bool preview() const { return preview_; }
  std::size_t avatar_count() const { return counts_.avatars.load(); }
  std::size_t person_count() const { return counts_.persons.load(); }
  /// Nobody keeps the room open here (owner: no person at all; bridge: no
  /// person connected to this node). On the room's strand.
  bool unpeopled() const;

  /// Starts the tick timer.
  void start();
  /// Stops ticking and drops the simulation; later requests are ignored.
  void close();

  // Requests; each runs later on the room's strand.
  /// Seats the joiner (welcome, stream header, presence to the others, then
  /// connection->joined), or closes its connection (room full).
  void join(JoinRequest request);
  /// Runs `done` on the room's strand once everything asked of the room
  /// before this call has been done (the joins of the demo room, say).
  void then(std::function<void()> done);
  /// `avatar`'s own face, built off the strand (OwnedRoom::give_own_face):
  /// its role wears it on the strand, if the room is still open.
  void wear_face(std::uint32_t avatar, std::string version, std::shared_ptr<const FaceModel> face);
  void leave(std::uint32_t avatar);
  void chat(std::uint32_t avatar, std::string text);
  void command(std::uint32_t avatar, codec::Command command);
  void resync(std::uint32_t avatar, std::vector<std::uint32_t> avatars);
  void set_rate(std::uint32_t avatar, std::uint32_t bps);
  /// The avatar `asset` was deleted by its uploader: whoever wears it here
  /// wears the procedural face of their name from now on, and everyone who
  /// sees them is sent its package.
  void replace_deleted_avatar(std::string asset);

  // Cluster (room_bus.hpp; owned_room_cluster.cpp, bridged_room.cpp).
  RoomRoleKind role() const { return kind_.load(); }
  /// Owner: a bridging node's request.
  void on_up(bridge::Up message);
  /// Bridge: the owner's news.
  void on_down(bridge::Down message);
  /// Becomes the owner of a room another node held: its members, their ids
  /// and join order, and their moods come back; the people on nodes that
  /// are not in `live_nodes` are kept away (PROTOCOL.md 10) until they come
  /// back with their resume key, or the rejoin grace ends.
  void take_over(std::vector<bridge::MemberRecord> members, std::optional<bridge::RoomState> state,
                 std::set<std::string> live_nodes);
  /// Owner: the people bridged from `node` are away (it stopped answering),
  /// or back (it answers again: it was only out of touch).
  void node_gone(std::string node);
  void node_back(std::string node);
  /// Owner: writes its whole record to Redis again (Redis came back).
  void keep_all();
  /// Bridge: asks the owner for its roster again (Redis came back).
  void ask_roster();
  /// Another node owns the room now (this one lost its lease while Redis
  /// was away): the local people are asked to come back, and are bridged.
  void step_down();

  // For the room's roles, on its strand.
  const RoomServices& services() const { return services_; }
  RoomCounts& counts() { return counts_; }
  RoomSimulation& simulation() { return simulation_; }
  /// A room without persons closes (unless persistent): when its last
  /// person leaves, when a join into a new room is refused, and at worst
  /// a second later (a room created for a hello that never arrived).
  void close_if_unpeopled();

 private:
  void do_join(JoinRequest request);
  /// The room emptied and closed while this hello was on its way: the
  /// joiner is seated in its successor.
  void join_successor(JoinRequest request);
  /// Runs `work` on the strand, after the tick under way if its faces are
  /// out on the worker pool (held_).
  template <class Work>
  void on_strand(Work work);
  /// Runs `work` on the strand while the room is open (after the tick under way).
  template <class Work>
  void post_open(Work work);
  std::chrono::microseconds tick_period() const;
  void schedule_tick();
  /// A tick: the role's first half, its faces stepped with the other rooms'
  /// (FaceStepper), then end_tick on the strand.
  void run_tick();
  void end_tick();

  RoomServices services_;
  RoomRegistry& registry_;
  std::string name_;
  bool persistent_;
  bool preview_;
  boost::asio::strand<boost::asio::thread_pool::executor_type> strand_;
  boost::asio::steady_timer timer_;
  /// Makes the simulation's lines' tracks on the server's SpeechWorker.
  std::shared_ptr<RoomTrackMaker> track_maker_;
  /// Lives as long as the room, whichever role simulates it.
  RoomSimulation simulation_;
  RoomCounts counts_;
  std::unique_ptr<RoomRole> role_;
  std::atomic<RoomRoleKind> kind_;
  std::chrono::steady_clock::time_point next_tick_;
  bool closed_ = false;
  /// A tick's faces are out on the worker pool (FaceStepper): the role and
  /// the simulation are the stepper's to finish first, so what comes to
  /// the strand meanwhile waits in held_, in order, until end_tick.
  bool ticking_ = false;
  std::vector<std::function<void()>> held_;
};

}  // namespace fw::server
