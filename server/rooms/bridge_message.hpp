#pragma once
// What the nodes of a cluster say to each other about one room, over Redis
// pub/sub (server/CLUSTER.md). The room's owner simulates it and sends its
// news *down* to every node that bridges clients into it; those nodes send
// their clients' requests *up* to the owner. Faces go down once per tick as
// exact parameters, so that every node runs the per-subscriber encoders of
// its own clients. Messages the clients read anyway (presence, seats,
// attention, chat, command results, speaking, unit morphs) travel as their
// encoded bytes.
//
// All nodes of a cluster run the same build: a message starts with a
// version byte, and one of another version is refused as unreadable.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/codec/messages.hpp"

namespace fw::server::bridge {

using Bytes = std::vector<std::uint8_t>;

/// 2: the language of a join and of a member, the speaking news.
/// 3: unit morphs: their news, and a member's set in its record.
/// 4: the faces' corrective weights (FaceParams schema 2).
inline constexpr std::uint8_t kVersion = 4;

/// A member as its owner keeps it in Redis, so that another node can
/// restore the room (and as the roster tells it to bridging nodes).
struct MemberRecord {
  codec::AvatarInfo info;
  std::string node;         ///< the node whose client it is; empty for the room's own faces
  std::string address;      ///< the person's address_key(), for the seats one address may hold
  std::string resume_hash;  ///< of the resume key the person holds: who shows it takes the seat back
  std::uint64_t order = 0;  ///< join order (the earliest present leads)
  std::string language;     ///< the language the person's lines are said in ("": the room's)
  /// The avatar's redefined units as an encoded unit morphs message
  /// (PROTOCOL.md 5.17), empty while its person never redefined one: in the
  /// roster, for a bridge's newcomers, and in Redis, for a successor.
  Bytes unit_morphs;
};

/// What the owner keeps of its room's behavior, once a second: each face's
/// mood. Who leads follows from the members' join order.
struct RoomState {
  struct Mood {
    std::uint32_t avatar = 0;
    std::vector<float> values;  ///< one per primary emotion
  };
  std::vector<Mood> moods;
};

// ---- down: owner -> bridging nodes ----------------------------------------
enum class DownKind : std::uint8_t {
  roster = 1, joined, refused, left, seats, attention, chat, result, tick, speaking, unit_morphs
};

struct FaceEntry {
  std::uint32_t id = 0;
  codec::FaceParams face;
};

struct Down {
  DownKind kind = DownKind::tick;
  std::string owner;                     ///< every message: the node that sent it
  std::vector<MemberRecord> members;     ///< roster
  Bytes attention;                       ///< roster (everyone's), attention (what changed): an encoded Attention
  std::string join_ref;                  ///< joined, refused: the up join it answers ("" for the owner's own)
  MemberRecord member;                   ///< joined
  bool returning = false;                ///< joined: a seat taken back (the others already know it)
  codec::CloseCode code = codec::CloseCode::normal;  ///< refused
  std::string reason;                    ///< refused
  std::uint32_t avatar = 0;              ///< left, unit_morphs: whose; result, chat notice: to whom (0: everyone)
  Bytes message;                         ///< seats, chat, result, speaking, unit_morphs: the encoded client message
  std::uint32_t tick = 0;                ///< tick
  std::vector<FaceEntry> faces;          ///< tick
};

// ---- up: bridging node -> owner ---------------------------------------------
enum class UpKind : std::uint8_t { sync = 1, join, leave, chat, command };

struct Up {
  UpKind kind = UpKind::sync;
  std::string node;        ///< every message: the node that sent it
  std::string join_ref;    ///< join
  std::string name;        ///< join
  std::string asset;       ///< join
  std::string address;     ///< join
  std::string resume_hash; ///< join: of the resume key the new connection holds
  std::string returning;   ///< join: the resume key the hello showed (to take a seat back), or ""
  std::string language;    ///< join: the language the person's lines are said in ("": the room's)
  std::uint32_t avatar = 0;  ///< leave, chat, command
  std::string text;        ///< chat
  Bytes command;           ///< command: an encoded Command
};

// Messages made whole, the fields their kind does not use left empty.
Down down_roster();
Down down_joined(std::string join_ref, MemberRecord member, bool returning = false);
Down down_refused(std::string join_ref, codec::CloseCode code, std::string reason);
Down down_left(std::uint32_t avatar);
/// seats, chat, result, speaking: a client message, for `avatar` (0: everyone);
/// unit_morphs: the set of `avatar`.
Down down_message(DownKind kind, std::uint32_t avatar, Bytes message);
Down down_attention(Bytes attention);
Down down_tick(std::uint32_t tick);
Up up_sync(std::string node);
Up up_leave(std::string node, std::uint32_t avatar);
Up up_chat(std::string node, std::uint32_t avatar, std::string text);
Up up_command(std::string node, std::uint32_t avatar, Bytes command);

Bytes encode(const Down& message);
Bytes encode(const Up& message);
Bytes encode(const MemberRecord& record);
/// nullopt when the bytes are not a message of this version.
std::optional<Down> decode_down(const std::uint8_t* data, std::size_t size);
std::optional<Up> decode_up(const std::uint8_t* data, std::size_t size);
Bytes encode(const RoomState& state);
std::optional<RoomState> decode_state(const std::uint8_t* data, std::size_t size);
std::optional<MemberRecord> decode_member(const std::uint8_t* data, std::size_t size);

}  // namespace fw::server::bridge
