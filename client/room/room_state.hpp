#pragma once
// What the network side knows of the room, shared with the render loop:
// the avatars, their decoders, their packages, the link statistics and the
// room's events. One mutex guards all of it; both sides hold it briefly
// (decoding a room frame, reading the faces of one output frame). The
// session (room_session.hpp) reads the protocol and calls the changes
// below; what they do to the room is decided here.
#include <chrono>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"
#include "link_stats.hpp"
#include "mute_list.hpp"
#include "package_assembler.hpp"
#include "room_scene.hpp"

namespace fw::client {

struct RoomAvatar {
  codec::AvatarInfo info;
  /// When its last frame was decoded: the face is extrapolated from there.
  std::chrono::steady_clock::time_point last_frame_at{};
  /// The newest complete package (preview, then full), and which it is.
  std::shared_ptr<const std::vector<std::uint8_t>> package;
  std::optional<codec::PackageChunk::Quality> package_quality;
  std::uint64_t package_serial = 0;  ///< grows with every new package, so the renderer sees a change
};

/// A line for the summary and for tests: chat lines and presence changes.
struct RoomEventRecord {
  std::string kind;  ///< "chat", "joined", "left", "speaking"
  std::string name;
  std::string text;  ///< chat and speaking only
  std::chrono::steady_clock::time_point at{};  ///< when it was recorded
  // speaking only (PROTOCOL.md 5.15):
  std::string language = {};
  std::uint32_t duration_ms = 0;
  std::uint32_t tick = 0;  ///< the room tick whose frame is the line's first
};

class RoomState {
 public:
  std::mutex mutex;

  bool joined = false;       ///< a welcome arrived on the current connection
  std::uint32_t you = 0;
  std::string room;
  std::string server;        ///< the URL of the server the session connects to (or last did)
  int tick_hz = 30;
  std::map<std::uint32_t, RoomAvatar> avatars;
  codec::RoomDecoder decoder;
  LinkStats stats;
  std::optional<codec::LinkStats> server_link;  ///< the server's last word on this link
  std::deque<RoomEventRecord> events;           ///< the last kMaxEvents
  /// Whom each avatar's face attends (PROTOCOL.md 5.14), as the server last said.
  std::map<std::uint32_t, codec::Attention::Entry> attention;
  /// Set when the client must stop: the server refused it for good (bad
  /// token, room full, ...), with what to do.
  std::optional<std::string> fatal_error;
  /// Whom the person muted for themselves (--mute): set before the session starts.
  MuteList mutes;
  /// Each avatar's redefined units (PROTOCOL.md 5.17), the newest version,
  /// until it leaves: the render loop draws its face with them.
  std::map<std::uint32_t, codec::UnitMorphs> unit_morphs;

  static constexpr std::size_t kMaxEvents = 200;
  using Clock = std::chrono::steady_clock;
  using PackageBytes = std::shared_ptr<const std::vector<std::uint8_t>>;

  void record(RoomEventRecord event) {
    event.at = Clock::now();
    events.push_back(std::move(event));
    if (events.size() > kMaxEvents) events.pop_front();
  }
  std::string name_of(std::uint32_t avatar) const {
    const auto it = avatars.find(avatar);
    return it == avatars.end() ? "avatar " + std::to_string(avatar) : it->second.info.name;
  }
  /// Whether the person muted this avatar (by its name; never their own).
  bool muted(std::uint32_t avatar) const { return mutes.mutes(avatar, name_of(avatar), you); }

  // Changes, made by the session with `mutex` held.

  /// A new connection: not joined until its welcome; its stream starts
  /// with a fresh decoder.
  void connection_started();
  /// The connection's codec stream header: a decoder for its options.
  void stream_started(const codec::StreamOptions& options) { decoder = codec::RoomDecoder(options); }
  /// The connection ended: no longer in the room (the avatars stay known).
  void connection_lost() { joined = false; }
  /// The server's welcome: the room and its avatars. An avatar still here
  /// under the same asset keeps its package (the server sends it again,
  /// but the face need not wait for it); `own_package`, when the client
  /// uploaded it, is its own face at once (the server sends none back).
  void welcomed(const codec::Welcome& welcome, const PackageBytes& own_package, Clock::time_point now);
  /// Presence: an avatar joined (recorded as an event).
  void avatar_joined(const codec::AvatarInfo& info);
  /// Presence: an avatar left; its decoder goes with it. Returns its name.
  std::string avatar_left(std::uint32_t avatar);
  /// An avatar's redefined units; an older version than the one kept is
  /// ignored (returns false).
  bool unit_morphs_arrived(const codec::UnitMorphs& morphs);
  /// The room was laid out again: the avatars' new seats.
  void seats_changed(const codec::Seats& seats);
  /// Faces whose attention changed.
  void attention_changed(const codec::Attention& message);
  /// A chat line (recorded as an event, or only counted when its writer is
  /// muted). Returns the writer's name.
  std::string chat_line(const codec::Chat& chat);
  /// A face begins to say a line (recorded as an event unless its writer is
  /// muted). Returns what the person reads, "[12.3 s] Anna says (de,
  /// 4650 ms): text" (seconds since the first welcome), or nothing when muted.
  std::optional<std::string> line_begun(const codec::Speaking& speaking, Clock::time_point now);
  /// A whole package: the avatar's face from now on. False when it is
  /// ignored: the avatar is not in the room, or a late preview would
  /// replace the full package.
  bool package_arrived(AssembledPackage package, Clock::time_point now);
  /// Decodes a room frame into the avatars' decoders, counting frames and
  /// errors. Returns whether at least one avatar's frame decoded.
  bool decode_room_frame(std::span<const std::uint8_t> room_frame, Clock::time_point now);

  /// Each avatar's face now (extrapolated from its last frame), in seat
  /// order (avatar id: the order they joined in). Avatars none of whose
  /// frames arrived yet are left out.
  std::vector<AvatarFace> faces(std::chrono::steady_clock::time_point now) const;

  /// What the room view draws now: everyone with their seat, attention and
  /// face (as faces() has it; a muted one still and neutral, its name
  /// marked), the last chat line shown as the caption.
  /// `your_name` names the self view before the welcome.
  RoomScene scene(std::chrono::steady_clock::time_point now, const std::string& your_name) const;
};

}  // namespace fw::client
