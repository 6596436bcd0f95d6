#pragma once
// A room another node of the cluster owns, relayed to the people connected
// here (RoomRole): their joins, chat, commands and leaving go up to the
// owner (bridge_message.hpp); the owner's roster, presence, seats,
// attention, chat, speaking, unit morphs and faces come down, and each
// tick's faces are encoded
// here for each person at their own rate, as the owner does for its own.
// Nothing is simulated here, and the owner decides every seat.
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "face_sources.hpp"
#include "room.hpp"
#include "room_role.hpp"

namespace fw::server {

class BridgedRoom : public RoomRole {
 public:
  explicit BridgedRoom(Room& room);

  RoomRoleKind kind() const override { return RoomRoleKind::bridge; }
  void join(JoinRequest request) override;
  void leave(std::uint32_t avatar) override;
  void chat(std::uint32_t avatar, std::string text) override;
  void command(std::uint32_t avatar, const codec::Command& command) override;
  void resync(std::uint32_t avatar, const std::vector<std::uint32_t>& avatars) override;
  void set_rate(std::uint32_t avatar, std::uint32_t bps) override;
  void replace_deleted_avatar(const std::string& asset) override;
  void tick(std::chrono::steady_clock::time_point due) override;
  bool unpeopled() const override { return counts_.local_persons.load() == 0; }
  bool awaiting_joins() const override { return !held_joins_.empty() || !sent_joins_.empty(); }
  void close() override;
  RoomHandover hand_over() override;
  void on_down(bridge::Down& message) override;
  void ask_roster() override;

 private:
  void on_roster(bridge::Down& message);
  void on_joined(bridge::Down& message);
  void on_left(std::uint32_t avatar);
  void on_tick(bridge::Down& message);
  /// `avatar`'s newest set of unit morphs (PROTOCOL.md 5.17) from the owner:
  /// kept for newcomers, and posted to the people here unless it is the set
  /// they were told already (a roster repeats every set).
  void on_unit_morphs(std::uint32_t avatar, bridge::Bytes set);
  /// Asks for the roster until it comes; gives up joins the owner did not answer.
  void housekeeping();
  void send_up(const bridge::Up& message);

  Room& room_;
  const RoomServices& services_;
  const std::string& name_;
  RoomCounts& counts_;
  /// Everyone as the owner last said; the people here have a stream.
  std::map<std::uint32_t, Member> members_;
  std::vector<AvatarFace> faces_;
  FaceSources face_sources_;  ///< faces_ as every stream's encoders see them
  std::vector<codec::FaceParams> bridged_faces_;
  /// Whom each face attended, as the owner last said (PROTOCOL.md 5.14).
  std::map<std::uint32_t, codec::Attention::Entry> attention_sent_;
  /// Each avatar's newest set of unit morphs, encoded, as the owner last said.
  std::map<std::uint32_t, SharedBytes> unit_morphs_;
  bool roster_ = false;                  ///< the owner's roster arrived
  std::vector<JoinRequest> held_joins_;  ///< waiting for the roster
  struct SentJoin {
    JoinRequest request;
    std::chrono::steady_clock::time_point sent;
  };
  std::map<std::string, SentJoin> sent_joins_;  ///< by join_ref, waiting for the owner's answer
  std::uint64_t next_join_ref_ = 1;
  std::chrono::steady_clock::time_point last_sync_{}, last_down_{};
  std::chrono::steady_clock::time_point last_resync_{};  ///< the last roster asked for because ticks disagreed
  std::uint32_t ticks_since_check_ = 0;  ///< for housekeeping four times a second
};

}  // namespace fw::server
