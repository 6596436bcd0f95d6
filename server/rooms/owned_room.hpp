#pragma once
// A room this node owns (RoomRole): it seats the joiners, simulates
// everyone (RoomSimulation) and streams their faces to the people here.
// In a cluster it also serves the people other nodes bridge to it: their
// joins, chat and commands come up, and it sends its news down once for
// every bridging node; it keeps its record in Redis for whoever takes it
// over, and it restores a room taken over from its record
// (owned_room_cluster.cpp). Alone, the bus it tells is LocalRoomBus, which
// forgets it all.
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "face_sources.hpp"
#include "room.hpp"
#include "room_role.hpp"
#include "token_bucket.hpp"

namespace fw::server {

/// What the owner keeps of each member beyond what every role does.
struct OwnedMember : Member {
  std::string address;      ///< a person's address_key()
  std::string node;         ///< the node a bridged person is on ("" here)
  std::string resume_hash;  ///< of the person's resume key
  std::uint64_t order = 0;  ///< join order (the earliest present leads)
  std::string language;     ///< the person's lines' ("": the room's), kept for a successor
  /// The person's node died; the seat waits for them until then.
  std::optional<std::chrono::steady_clock::time_point> away_until;
  bool person() const { return stream || !node.empty() || away_until; }
};

class OwnedRoom : public RoomRole {
 public:
  explicit OwnedRoom(Room& room);

  RoomRoleKind kind() const override { return RoomRoleKind::owner; }
  void join(JoinRequest request) override;
  void leave(std::uint32_t avatar) override;
  void chat(std::uint32_t avatar, std::string text) override;
  void command(std::uint32_t avatar, const codec::Command& command) override;
  void resync(std::uint32_t avatar, const std::vector<std::uint32_t>& avatars) override;
  void set_rate(std::uint32_t avatar, std::uint32_t bps) override;
  void replace_deleted_avatar(const std::string& asset) override;
  /// begin_tick, the faces stepped here, finish_tick.
  void tick(std::chrono::steady_clock::time_point due) override;
  RoomSimulation::TickFaces begin_tick(std::chrono::steady_clock::time_point due) override;
  void finish_tick() override;
  bool unpeopled() const override { return counts_.persons.load() == 0; }
  void close() override;
  RoomHandover hand_over() override;

  // Cluster (owned_room_cluster.cpp).
  void on_up(bridge::Up& message) override;
  void node_gone(const std::string& node) override;
  void node_back(const std::string& node) override;
  void keep_all() override;
  void step_down() override;
  void wear_face(std::uint32_t avatar, const std::string& version, std::shared_ptr<const FaceModel> face) override;
  /// Seats again the members of the record of a room taken over, in join
  /// order and under their ids, with the people connected here (`here`)
  /// keeping their streams; the people on nodes not in `live_nodes` are
  /// kept away until they come back or the rejoin grace ends.
  void restore(std::vector<bridge::MemberRecord> records, std::optional<bridge::RoomState> state,
               const std::set<std::string>& live_nodes, std::map<std::uint32_t, Member> here);

 private:
  // Seating (owned_room.cpp).
  /// Why `request` cannot be seated (room full, its address holds its
  /// share of seats, no avatar id free), or nullopt.
  std::optional<std::pair<codec::CloseCode, std::string>> refusal_of(const JoinRequest& request);
  void refuse(const JoinRequest& request, codec::CloseCode code, const std::string& why);
  /// Seats the people from `address` hold here.
  std::size_t seats_of(const std::string& address) const;
  /// Seats held by people from `block` (address_group()).
  std::size_t seats_of_block(const std::string& block) const;
  /// `avatar`'s own face from its package `face`: at once when already
  /// built, else built on the worker pool and worn when back (the generic
  /// face meanwhile), so a join never waits for a build.
  void give_own_face(std::uint32_t avatar, const StoredAvatar& face);
  /// A line from the server (avatar 0) to one person only.
  void notice(OwnedMember& member, const std::string& text);
  /// `avatar` begins to say a line: a speaking message to everyone (5.15).
  void tell_line_begun(std::uint32_t avatar, const RoomEvent::LineBegun& line);
  /// `avatar`'s person redefined its units: the unit morphs message (5.17)
  /// to everyone here.
  void broadcast_unit_morphs(std::uint32_t avatar);
  /// Every avatar's redefined units to a member just welcomed.
  void send_unit_morphs(OwnedMember& member);
  /// A preview's: its simulated skin beyond its frames' action units to
  /// its page (PROTOCOL.md 5.18), at most kPreviewSurfaceHz, when changed.
  void send_preview_surface();
  /// Takes every member's seat from the simulation; a Seats message for
  /// everyone when a seat already announced moved, else null.
  SharedBytes reseat();
  /// Everyone's attention now, and the message that says it.
  codec::Attention attention_now() const;
  /// After a tick: the attention that changed goes to everyone.
  void send_attention_changes();
  void broadcast_seats(const SharedBytes& message);
  void broadcast_attention(const codec::Attention& attention, std::uint32_t except = UINT32_MAX);

  // What the bus carries (owned_room_cluster.cpp).
  bridge::MemberRecord record_of(const OwnedMember& member) const;
  void send_down(const bridge::Down& message);
  void keep(const OwnedMember& member);
  /// Members bridged from other nodes, and not away.
  std::size_t bridged_members() const;
  void answer_sync();
  void keep_state();
  /// The redefined units `record` kept, given back to its avatar (restore).
  void restore_unit_morphs(const bridge::MemberRecord& record);
  void let_away_go();
  /// A person coming back with the resume key of a seat kept away: true if
  /// `request` took it.
  bool take_seat_back(JoinRequest& request);

  Room& room_;
  const RoomServices& services_;
  const std::string& name_;
  RoomSimulation& simulation_;
  RoomCounts& counts_;
  std::map<std::uint32_t, OwnedMember> members_;
  std::vector<AvatarFace> faces_;
  FaceSources face_sources_;  ///< faces_ as every stream's encoders see them
  /// Whom each face attended in the last Attention sent (PROTOCOL.md 5.14).
  std::map<std::uint32_t, codec::Attention::Entry> attention_sent_;
  std::uint64_t next_order_ = 1;
  TokenBucket chat_rate_;  ///< chat lines into this room, from everyone (AbuseLimits::room_chat)
  TokenBucket join_rate_;  ///< joins into this room, from everyone (AbuseLimits::room_joins)
  std::uint32_t ticks_since_check_ = 0;
  /// The work of the tick under way so far (its first half), for Metrics::observe_tick.
  std::chrono::steady_clock::duration tick_work_{};  ///< for close_if_unpeopled once a second
  /// A preview's surface residual last sent to its page, per avatar (none: empty).
  std::map<std::uint32_t, std::vector<codec::UnitMorphs::Move>> preview_surface_sent_;
  /// The residual changes with every tick while the face moves: ten a
  /// second keep a muscle's pull visible as it builds up (the tissue
  /// follows its muscle over a few hundred ms: its slowest modes are near
  /// 5 Hz) at a few KB a second on the page's own link.
  static constexpr std::uint32_t kPreviewSurfaceHz = 10;
};

}  // namespace fw::server
