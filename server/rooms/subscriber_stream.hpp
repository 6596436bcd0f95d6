#pragma once
// One subscriber's view of its room: an Encoder per avatar, the packages it
// still has to receive, and the rate control that keeps everything it is
// sent under its budget. Owned and called by the room, on the room's strand.
//
// Every tick: if the connection still holds more than half a second of
// budget, the tick is skipped for this subscriber (the encoders hold, so
// nothing is lost: the next frame predicts from what the client has);
// otherwise every avatar's face is offered to its encoder and the frames
// that come out go in one room frame. On a thin budget only every second
// tick (15 Hz) carries frames, so that one room frame bundles them all. Package chunks fill what the budget
// leaves, previews first; an avatar's frames start once its preview is
// there (before, the client could not draw them). Once a second the budget follows what actually
// drained: down when ticks were skipped, back up toward the client's own.
//
// The room's other messages go through the same budget: they go at once
// while the budget is overdrawn by less than half a second of it, else wait
// here for the ticks to pay it back. Presence, seats,
// attention and command results go first, and while one of them waits no
// room frame or package chunk goes (so a face's frames never arrive before
// the presence that introduces it); waiting ones are coalesced (a joined
// and a left of the same avatar cancel, the newest seats replace older
// ones, attention entries merge). Chat lines go next; while they wait the
// faces' share of the budget shrinks as it does for packages, and past
// kMaxWaitingChat lines (or a few seconds of budget) the oldest are dropped
// and the client told how many, in a line from avatar 0 (the server).
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "avatar_face.hpp"
#include "fw/codec/codec.hpp"
#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"
#include "metrics.hpp"
#include "room_connection.hpp"
#include "viewer_encoding.hpp"

namespace fw::server {

struct StreamSettings {
  int tick_hz = 30;
  std::uint32_t budget_bps = 64000;  ///< the client's, already capped by the server
  bool timestamps = false;
  bool packages = true;
  bool own_package = false;  ///< the subscriber holds its own avatar's package
  /// The hello's version: the welcome answers in it, and only sessions of
  /// codec::kFirstSpeakingVersion or later are sent speaking messages, of
  /// codec::kFirstUnitMorphsVersion or later unit morphs.
  std::uint16_t protocol_version = codec::kProtocolVersion;
};

class SubscriberStream {
 public:
  SubscriberStream(const StreamSettings& settings, std::shared_ptr<RoomConnection> connection, Metrics& metrics);

  void add_avatar(std::uint32_t avatar, SharedBytes preview, SharedBytes full);
  void remove_avatar(std::uint32_t avatar);
  /// `avatar` wears another face from now on (its own was deleted): its
  /// full package is sent again, which a client puts in place of the one it
  /// holds (PROTOCOL.md 5.7).
  void replace_package(std::uint32_t avatar, SharedBytes preview, SharedBytes full);
  /// The client lost track of these avatars (a resync request); empty: all.
  void force_key_frames(std::span<const std::uint32_t> avatars);
  /// A new budget from the client (0: the server's default, resolved by the caller).
  void set_budget(std::uint32_t bps);
  /// Charges a message the room sent outside the stream (the welcome and
  /// the attention that follows it).
  void charge(std::size_t bytes);

  // Room messages, sent within the budget (above).
  void post_presence(codec::Presence::Change change, std::uint32_t avatar, SharedBytes message);
  void post_seats(SharedBytes message);
  void post_attention(const codec::Attention& attention);
  void post_result(SharedBytes message);
  /// A chat line (from an avatar, or the server's avatar 0).
  void post_chat(SharedBytes message);
  /// A face begins to say a line (codec::Speaking), for sessions of protocol
  /// version 4 or later only (a version-3 client would refuse it). It goes
  /// before any later room frame, which carries the line: it waits with
  /// presence and the rest, kMaxWaitingSpeaking at most (the oldest goes).
  void post_speaking(SharedBytes message);
  /// An avatar's redefined units (codec::UnitMorphs, the whole set), for
  /// sessions of protocol version 5 or later only. It waits with presence
  /// and the rest (after the presence that introduces the avatar, before
  /// any later frame of it); a newer one for the same avatar replaces one
  /// still waiting, and one for a face the client never heard of goes with it.
  void post_unit_morphs(std::uint32_t avatar, SharedBytes message);
  /// A face-lab preview's surface residual (codec::PreviewSurface, PROTOCOL.md
  /// 5.18), for the connection that owns the preview only (of protocol
  /// version 5 or later). It waits with
  /// the room's messages; a newer one replaces one still waiting (each
  /// holds the whole residual).
  void post_preview_surface(SharedBytes message);
  /// Room messages still waiting, and chat lines dropped so far.
  std::size_t waiting_messages() const { return waiting_.size() + chat_.size(); }
  std::uint64_t dropped_chat_lines() const { return dropped_chat_total_; }

  static constexpr std::size_t kMaxWaitingChat = 16;
  static constexpr std::size_t kMaxWaitingResults = 16;
  static constexpr std::size_t kMaxWaitingSpeaking = 8;

  void tick(std::uint32_t tick, std::uint64_t now_us, std::span<const AvatarFace> faces);

  const std::shared_ptr<RoomConnection>& connection() const { return connection_; }
  std::uint32_t target_bps() const { return static_cast<std::uint32_t>(effective_bps_); }

 private:
  struct PackageSend {
    std::uint32_t avatar;
    codec::PackageChunk::Quality quality;
    SharedBytes bytes;
    std::size_t offset = 0;
  };
  enum class Kind { joined, left, seats, attention, result, speaking, unit_morphs, preview_surface };
  struct Waiting {
    Kind kind;
    std::uint32_t avatar = 0;  ///< joined, left, unit_morphs: whose
    SharedBytes bytes;         ///< null for the attention (encoded when it goes)
  };
  /// Queues a message of `kind`, dropping the oldest of its kind past `max_waiting`.
  void post_bounded(Kind kind, std::size_t max_waiting, SharedBytes message);
  /// Half a second of budget or more waits for the socket.
  bool congested() const;
  bool may_send_message() const;
  /// What waits and the budget allows, unless the socket is congested.
  void send_messages();
  /// Presence, seats, attention and results while the budget allows; true
  /// once none waits.
  bool send_waiting();
  void send_chat();
  void drop_oldest_chat();
  /// Faces' share of the budget for what else waits (packages, chat).
  double param_share() const;
  void send_room_frames(std::uint32_t tick, std::uint64_t now_us, std::span<const codec::RoomEntry> entries);
  void send_package_chunks();
  void once_a_second(std::uint64_t now_us);
  void retarget_encoders();
  std::uint32_t bundle_ticks() const;
  double weight_of(std::uint32_t avatar) const;
  void rebalance(double seconds);
  std::size_t send(SharedBytes message);

  StreamSettings settings_;
  std::shared_ptr<RoomConnection> connection_;
  Metrics& metrics_;
  std::map<std::uint32_t, ViewerEncoding> encoders_;
  struct Fairness {
    double weight = 1.0;  ///< the avatar's share of the parameter budget, relative to an equal one
    std::uint64_t frames_at_second_start = 0;
  };
  std::map<std::uint32_t, Fairness> fairness_;
  std::deque<PackageSend> packages_;
  std::set<std::uint32_t> awaiting_preview_;  ///< avatars whose preview is not complete yet
  std::deque<Waiting> waiting_;
  std::vector<codec::Attention::Entry> waiting_attention_;  ///< the waiting attention message's entries
  std::deque<SharedBytes> chat_;
  std::size_t chat_bytes_ = 0;
  std::uint64_t dropped_chat_ = 0;  ///< since the last notice
  std::uint64_t dropped_chat_total_ = 0;
  bool chat_share_ = false;  ///< the faces' share is lowered for waiting chat
  double effective_bps_;
  double credit_bytes_ = 0;     ///< what the budget allows to send now
  std::uint64_t second_start_us_ = 0;
  std::uint64_t written_at_second_start_ = 0;
  bool congested_this_second_ = false;
  std::uint32_t skipped_ticks_ = 0;
  std::vector<std::uint8_t> frame_;
  std::vector<codec::RoomEntry> entries_;
};

}  // namespace fw::server
