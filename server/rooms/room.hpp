#pragma once
// One room: its avatars, their simulation (behavior + physics) and a
// SubscriberStream per connected person. Everything runs on the room's
// strand on the worker pool, never in an I/O handler: sessions post their
// requests here, and the tick timer simulates, encodes and hands finished
// messages to the connections.
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>

#include "avatar_store.hpp"
#include "bridge_message.hpp"
#include "fw/codec/messages.hpp"
#include "room_connection.hpp"
#include "room_simulation.hpp"
#include "server_context.hpp"
#include "subscriber_stream.hpp"
#include "token_bucket.hpp"

namespace fw::server {

struct JoinRequest {
  std::string name;
  StoredAvatar avatar;
  StreamSettings stream;
  std::shared_ptr<RoomConnection> connection;  ///< null for the room's own autonomous avatars
  std::string resume;  ///< the connection's resume key, for its welcome
  /// The person's address (address_key()), for the seats one address may
  /// hold; empty for autonomous avatars.
  std::string address;
  /// The resume key the hello showed (PROTOCOL.md 5.1): in a cluster, a
  /// person whose node died takes their seat back with it.
  std::string returning;
  // A join bridged from another node (cluster): that node and its reference.
  std::string node;
  std::string join_ref;
  std::string resume_hash;  ///< of `resume`, when the connection is on another node
};

/// Who simulates a room: this node (the owner; always, in one process), or
/// another node of the cluster whose news this one bridges to its clients.
enum class RoomRole { owner, bridge };

class Room : public std::enable_shared_from_this<Room> {
 public:
  Room(ServerContext& context, std::string name, bool persistent, std::uint64_t seed,
       RoomRole role = RoomRole::owner);
  ~Room();

  const std::string& name() const { return name_; }
  bool persistent() const { return persistent_; }
  std::size_t avatar_count() const { return avatar_count_.load(); }
  std::size_t person_count() const { return person_count_.load(); }
  /// Nobody keeps the room open here: owner, no person at all; bridge, no
  /// person connected to this node.
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
  void leave(std::uint32_t avatar);
  void chat(std::uint32_t avatar, std::string text);
  void command(std::uint32_t avatar, codec::Command command);
  void resync(std::uint32_t avatar, std::vector<std::uint32_t> avatars);
  void set_rate(std::uint32_t avatar, std::uint32_t bps);
  /// The avatar `asset` was deleted by its uploader: whoever wears it here
  /// wears the procedural face of their name from now on, and everyone who
  /// sees them is sent its package (room_deleted_avatar.cpp).
  void replace_deleted_avatar(std::string asset);

  // Cluster (room_bus.hpp, room_bridge.cpp, room_takeover.cpp).
  RoomRole role() const { return role_.load(); }
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

 private:
  struct Member {
    codec::AvatarInfo info;
    StoredAvatar avatar;
    std::unique_ptr<SubscriberStream> stream;  ///< null for autonomous avatars
    std::string address;                       ///< a person's address_key()
    std::string node;         ///< owner: the node a bridged person is on ("" here)
    std::string resume_hash;  ///< owner: of the person's resume key
    std::uint64_t order = 0;  ///< owner: join order (the earliest present leads)
    /// Owner: the person's node died; the seat waits for them until then.
    std::optional<std::chrono::steady_clock::time_point> away_until;
    bool local_gone = false;  ///< bridge: the local connection left; the owner's `left` is awaited
    bool person() const { return stream || !node.empty() || away_until || local_gone; }
  };
  // Bridging (room_bridge.cpp).
  bridge::MemberRecord record_of(const Member& member) const;
  void send_down(const bridge::Down& message);
  void keep(const Member& member);
  std::size_t bridged_members() const;
  void answer_sync();
  void bridge_join(JoinRequest request);
  void on_roster(bridge::Down& message);
  void on_joined(bridge::Down& message);
  void on_left(std::uint32_t avatar);
  void bridge_tick(bridge::Down& message);
  void bridge_housekeeping();
  /// The StoredAvatar of a member another node seated (a demo face, the
  /// store, or the cluster's copy).
  StoredAvatar avatar_of(const codec::AvatarInfo& info) const;
  // Owner housekeeping in a cluster (room_takeover.cpp).
  void keep_state();
  void let_away_go();
  /// A person coming back with the resume key of a seat kept away: true if
  /// `request` took it.
  bool take_seat_back(JoinRequest& request);
  void do_join(JoinRequest request);
  void join_successor(JoinRequest request);
  /// Why `request` cannot be seated (room full, its address holds its
  /// share of seats, no avatar id free), or nullopt.
  std::optional<std::pair<codec::CloseCode, std::string>> refusal_of(const JoinRequest& request);
  void refuse(const JoinRequest& request, codec::CloseCode code, const std::string& why);
  /// Seats the people from `address` hold here.
  std::size_t seats_of(const std::string& address) const;
  /// Seats held by people from `block` (address_group()).
  std::size_t seats_of_block(const std::string& block) const;
  void do_chat(std::uint32_t avatar, std::string text);
  /// A line from the server (avatar 0) to one person only.
  void notice(Member& member, const std::string& text);
  /// A room without persons closes (unless persistent): when its last
  /// person leaves, when a join into a new room is refused, and at worst
  /// a second later (a room created for a hello that never arrived).
  void close_if_unpeopled();
  /// Presence to everyone already seated, and the newcomer's face in their streams.
  void introduce_to_others(const Member& newcomer);
  /// The welcome to a person who joins, and the stream that follows it.
  std::unique_ptr<SubscriberStream> welcome(const Member& newcomer, const JoinRequest& request);
  void do_leave(std::uint32_t avatar);
  /// Takes every member's seat from the simulation; a Seats message for
  /// everyone when a seat already announced moved, else null.
  SharedBytes reseat();
  /// Everyone's attention now, and the message that says it.
  codec::Attention attention_now() const;
  /// After a tick: the attention that changed goes to everyone.
  void send_attention_changes();
  void broadcast_seats(const SharedBytes& message);
  void broadcast_attention(const codec::Attention& attention, std::uint32_t except = UINT32_MAX);
  std::chrono::microseconds tick_period() const;
  void schedule_tick();
  void on_tick();

  ServerContext& context_;
  std::string name_;
  bool persistent_;
  boost::asio::strand<boost::asio::thread_pool::executor_type> strand_;
  boost::asio::steady_timer timer_;
  RoomSimulation simulation_;
  std::map<std::uint32_t, Member> members_;
  std::vector<AvatarFace> faces_;
  /// Whom each face attended in the last Attention sent (PROTOCOL.md 5.14).
  std::map<std::uint32_t, codec::Attention::Entry> attention_sent_;
  std::chrono::steady_clock::time_point next_tick_;
  std::size_t kinematic_faces_ = 0;  ///< this room's share of Metrics::kinematic_faces
  bool closed_ = false;
  std::atomic<RoomRole> role_;
  std::uint64_t next_order_ = 1;
  // Bridge role.
  bool roster_ = false;                          ///< the owner's roster arrived
  std::vector<JoinRequest> held_joins_;          ///< waiting for the roster
  struct SentJoin {
    JoinRequest request;
    std::chrono::steady_clock::time_point sent;
  };
  std::map<std::string, SentJoin> sent_joins_;   ///< by join_ref, waiting for the owner's answer
  std::uint64_t next_join_ref_ = 1;
  std::vector<codec::FaceParams> bridged_faces_;
  std::chrono::steady_clock::time_point last_sync_{}, last_down_{};
  TokenBucket chat_rate_;  ///< chat lines into this room, from everyone (AbuseLimits::room_chat)
  TokenBucket join_rate_;  ///< joins into this room, from everyone (AbuseLimits::room_joins)
  std::uint32_t ticks_since_check_ = 0;  ///< for close_if_unpeopled once a second
  std::atomic<int> pending_joins_{0};  ///< joins posted and not yet done
  std::atomic<std::size_t> avatar_count_{0};
  std::atomic<std::size_t> person_count_{0};  ///< everyone's, bridged and away too
  std::atomic<std::size_t> local_persons_{0};  ///< people connected to this node
};

}  // namespace fw::server
