#pragma once
// The room protocol's session messages (server/PROTOCOL.md is the normative
// description; this header is its C++ API): hello, welcome, presence, chat,
// commands, package chunks, rate, ping/pong, link statistics, closing, timed
// room frames, seats, attention and speaking, plus the length prefix that
// delimits messages on TCP.
//
// Every message is one WebSocket binary message, or one length-prefixed frame
// on TCP. A session message's first byte is 0x80 | MessageType; the codec's
// own messages (stream header 0x10, room frame 0x13, resync request 0x14)
// travel on the same connection unchanged, and classify() tells them apart.
//
// Readers are bounded: every string, count and number has a limit, nothing
// is allocated past it, and bad bytes give a MessageError, never an exception.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fw::codec {

/// The session protocol's version, carried in hello and welcome. A server
/// answers a hello of another version with Closing{unsupported_version}.
/// Version 2 added the seats (in avatar_info, and the seats message) and the
/// attention message; version 4 the hello's language and the speaking
/// message; version 5 the unit morphs message. A server still reads a
/// version-3 or 4 hello and answers it with a welcome of its version, whose
/// layout is the same.
inline constexpr std::uint16_t kProtocolVersion = 5;
/// The oldest version a hello or welcome may carry and still be read.
inline constexpr std::uint16_t kOldestProtocolVersion = 3;
/// The first version whose hello carries a language and whose sessions are
/// sent speaking messages.
inline constexpr std::uint16_t kFirstSpeakingVersion = 4;
/// The first version whose sessions are sent unit morphs messages.
inline constexpr std::uint16_t kFirstUnitMorphsVersion = 5;

/// The low seven bits of a session message's first byte. Values never change.
enum class MessageType : std::uint8_t {
  hello = 1,             ///< up: first message of a connection
  welcome = 2,           ///< down: the answer to hello (room state)
  presence = 3,          ///< down: an avatar joined or left
  chat = 4,              ///< both: a chat line
  command = 5,           ///< up: a command to one's own avatar
  command_result = 6,    ///< down: whether a command was accepted
  package_chunk = 7,     ///< down: a piece of an avatar package
  set_rate = 8,          ///< up: a new downstream budget
  ping = 9,              ///< up: clock and round-trip probe
  pong = 10,             ///< down: the answer to ping
  link_stats = 11,       ///< down: what the server measures of the link
  closing = 12,          ///< down: why the server closes the connection (last message)
  timed_room_frame = 13, ///< down: a codec room frame with its tick and server time
  seats = 14,            ///< down: where every avatar sits, after the layout changed
  attention = 15,        ///< down: whom faces attend, for those whose target changed
  speaking = 16,         ///< down (version 4): a face begins to say a chat line
  unit_morphs = 17,      ///< down (version 5): an avatar's action units as its person redefined them
  preview_surface = 18,  ///< down, face-lab previews only: what of the simulated skin the action units do not show
};
inline constexpr MessageType kLastMessageType = MessageType::preview_surface;
inline constexpr std::uint8_t kSessionMessageBit = 0x80;

/// What a message on the connection is, from its first byte.
enum class MessageKind : std::uint8_t {
  invalid,         ///< empty, or a first byte no message starts with
  stream_header,   ///< codec stream header (0x10)
  room_frame,      ///< codec room frame (0x13)
  resync_request,  ///< codec resync request (0x14)
  session,         ///< 0x80 | MessageType (a known type)
};
MessageKind classify(std::span<const std::uint8_t> message);
/// The session message's type; only meaningful when classify() says session.
MessageType session_type(std::span<const std::uint8_t> message);

/// Why a message was refused. Values never change; new codes get new numbers.
enum class MessageError : std::uint8_t {
  ok = 0,
  empty = 1,                ///< zero bytes
  not_session_message = 2,  ///< the first byte's high bit is clear (a codec message, or garbage)
  unknown_type = 3,         ///< 0x80 | a type this version does not know
  wrong_type = 4,           ///< a known type, but not the one this call reads
  truncated = 5,            ///< a field runs past the end of the message
  too_large = 6,            ///< over the message's size limit
  string_too_long = 7,      ///< a string over its field's limit
  bad_text = 8,             ///< a string that is not UTF-8, or holds control characters; a language not of a-z 0-9 -
  value_out_of_range = 9,   ///< a number outside what its field allows
  trailing_bytes = 10,      ///< bytes after the last field
  too_many_entries = 11,    ///< a list over its limit
  unsupported_version = 12, ///< a hello or welcome of another protocol version
  bad_flags = 13,           ///< reserved flag bits set
  bad_number = 14,          ///< a number written in more bytes than it needs or than its field allows
};
/// A sentence for a person: what was wrong with the message.
std::string_view describe(MessageError error);

// ---------------------------------------------------------------------------
// Limits (PROTOCOL.md, "Limits").

inline constexpr std::size_t kMaxUpstreamMessageBytes = 8 * 1024;
/// A 64 KiB codec room frame plus the timed frame's prefix fits.
inline constexpr std::size_t kMaxDownstreamMessageBytes = 64 * 1024 + 64;
inline constexpr std::size_t kMaxRoomNameBytes = 64;
inline constexpr std::size_t kMaxDisplayNameBytes = 32;
inline constexpr std::size_t kMaxAssetIdBytes = 64;
inline constexpr std::size_t kMaxTokenBytes = 512;
/// An avatar key (the secret an upload returns) and a resume key (a welcome's).
inline constexpr std::size_t kMaxKeyBytes = 64;
inline constexpr std::size_t kMaxChatBytes = 500;
/// A language: an espeak-ng voice name such as `en`, `en-us`, `pt-br`.
inline constexpr std::size_t kMaxLanguageBytes = 16;
/// The longest line a face says at once is 15 s of speech (longer lines
/// are said in part); 20 s leaves room for espeak-ng's pauses.
inline constexpr std::uint32_t kMaxSpeakingMs = 20'000;
inline constexpr std::size_t kMaxEmotionBytes = 16;
inline constexpr std::size_t kMaxSentenceBytes = 4096;
/// A saved look's name (play look, PROTOCOL.md 5.5): what a person reads in a picker.
inline constexpr std::size_t kMaxLookNameBytes = 32;
inline constexpr std::size_t kMaxReasonBytes = 120;
inline constexpr std::size_t kMaxWelcomeAvatars = 64;
inline constexpr std::size_t kMaxPackageBytes = 8 * 1024 * 1024;
inline constexpr std::size_t kMaxChunkBytes = 16 * 1024;
inline constexpr std::uint32_t kMaxBitsPerSecond = 100'000'000;
inline constexpr std::uint32_t kMaxCommandMs = 600'000;
inline constexpr std::uint32_t kMaxAvatarIdValue = (1u << 21) - 1;  ///< as codec::kMaxAvatarId
/// A seat's facing in ten-thousandths of a radian: pi.
inline constexpr std::int16_t kMaxFacingTenThousandths = 31416;
/// Unit morphs: channels one avatar may have redefined at once (4 action
/// units, both sides of each), and skin vertices one morph may move (the
/// generic face has 228; a client refuses indices past its own face's).
inline constexpr std::size_t kMaxRedefinedChannels = 8;
inline constexpr std::size_t kMaxUnitMorphMoves = 1024;
/// A unit morph's displacements are written in steps of 1/4096 model unit
/// (15 micrometres on an average face), as signed 16-bit numbers.
inline constexpr float kUnitMorphStepsPerUnit = 4096.0f;

// ---------------------------------------------------------------------------
// Messages.

/// Up, first message of a connection.
struct Hello {
  std::uint16_t protocol_version = kProtocolVersion;
  std::string room;    ///< 1 .. 64 bytes
  std::string name;    ///< display name, 1 .. 32 bytes
  std::string avatar;  ///< asset id of an uploaded package; empty: the server makes a procedural face
  std::string token;   ///< join token; empty when the server needs none
  /// The secret the upload of `avatar` returned: only who uploaded a face
  /// may wear it. Empty with no `avatar`.
  std::string avatar_key;
  /// A previous welcome's resume key, when this connection replaces one
  /// that dropped: it takes over the join token the old one still holds.
  std::string resume;
  /// Downstream budget in bits per second, every byte of every message
  /// counted; 0: the server's default.
  std::uint32_t max_bps = 0;
  /// Room frames arrive as timed room frames (tick and server time, for
  /// latency measurements) instead of bare codec room frames.
  bool timestamps = false;
  /// No package chunks on this connection (the client fetches packages over HTTP).
  bool no_packages = false;
  /// The client holds its own avatar's package (it uploaded the package
  /// itself): none of its own avatar's packages come back down.
  bool own_package = false;
  /// A face-lab preview (PROTOCOL.md 5.16): the person is seated alone in a
  /// private room of their own, which nobody else can list or join, and
  /// the room's name in the hello is not used.
  bool preview = false;
  /// Version 4: the language the person's chat lines are said in, an
  /// espeak-ng voice name (is_language_code); empty: the server's default.
  /// A version-3 hello has none (it must stay empty to be written).
  std::string language;
};

/// Whether `code` is 1 .. kMaxLanguageBytes of lowercase ASCII letters,
/// digits and `-`: the shape of a language (whether a server speaks it is
/// the server's to say).
bool is_language_code(std::string_view code);

/// Where an avatar sits in the room frame the server's gaze is computed in
/// (PROTOCOL.md 4): millimetres, x to the right of someone looking at the
/// arc, y up, z toward that onlooker; the head turned `facing_yaw_rad` about
/// y (positive toward the person's own left). Carried as whole millimetres
/// (|v| <= 32 767) and ten-thousandths of a radian (|facing| <= pi).
struct SeatInfo {
  float x_mm = 0, y_mm = 0, z_mm = 0;
  float facing_yaw_rad = 0;
  bool operator==(const SeatInfo&) const = default;
};

/// One avatar in the room.
struct AvatarInfo {
  std::uint32_t id = 0;  ///< the room-frame avatar id
  std::string name;
  std::string asset;     ///< asset id (GET /api/packages/ASSET)
  std::uint32_t preview_bytes = 0;  ///< size of the preview package, 0 if none
  std::uint32_t full_bytes = 0;     ///< size of the full package
  bool person = true;               ///< false for the room's autonomous avatars
  SeatInfo seat;                    ///< its place at the table
};

/// Down, the answer to hello; the codec stream header follows it.
struct Welcome {
  std::uint16_t protocol_version = kProtocolVersion;
  std::uint32_t you = 0;       ///< the joining connection's own avatar id
  std::string room;
  std::uint8_t tick_hz = 30;   ///< simulation ticks per second
  std::uint32_t max_bps = 0;   ///< the downstream budget the server starts with
  std::vector<AvatarInfo> avatars;  ///< everybody in the room, the joiner included
  /// Kept by the client and sent in the hello of its next connection after
  /// a drop, so that it resumes in place of this one (a token admits one
  /// connection at a time).
  std::string resume;
};

/// Down: an avatar joined (with everything about it) or left (id only).
struct Presence {
  enum class Change : std::uint8_t { joined = 0, left = 1 };
  Change change = Change::joined;
  AvatarInfo avatar;
};

/// Up: a line typed by the person (`from` ignored). Down: from an avatar.
struct Chat {
  std::uint32_t from = 0;
  std::string text;  ///< 1 .. 500 bytes of UTF-8
};

/// Up: a command to one's own avatar.
/// What a face-lab override sets (PROTOCOL.md 5.16); `reset` clears them all.
enum class OverridePart : std::uint8_t {
  emotion = 0, action_unit = 1, head_yaw = 2, head_pitch = 3, head_roll = 4, eye_yaw = 5, eye_pitch = 6,
  lids = 7, blush = 8, pallor = 9, behaviour = 10, reset = 11,
  muscle = 12, skin_age = 13, skin_looseness = 14,  ///< the physics face's own level
};
inline constexpr std::uint8_t kLastOverridePart = static_cast<std::uint8_t>(OverridePart::skin_looseness);

/// One override of a face-lab preview: held until set again or reset.
struct FaceOverride {
  OverridePart part = OverridePart::emotion;
  std::uint8_t index = 0;  ///< emotion 0 .. 5 (joy .. disgust), a FACS AU number, a colour region 0 .. 4, a muscle 0 .. 41
  std::uint8_t side = 0;   ///< action unit and lids: 0 both, 1 left, 2 right
  std::int16_t value = 0;  ///< ten-thousandths: of an intensity (0 .. 10000) or of a radian; behaviour 0 off, 1 on
  bool operator==(const FaceOverride&) const = default;
};

struct Command {
  /// override and check: a face lab's (PROTOCOL.md 5.16); play_look: a
  /// script its avatar's owner saved (PROTOCOL.md 8.2), played as facs.
  enum class Kind : std::uint8_t {
    express = 0, look_at = 1, snub = 2, facs = 3, override_face = 4, check = 5, play_look = 6
  };
  std::uint32_t request_id = 0;  ///< echoed in the result
  Kind kind = Kind::express;
  std::string emotion;           ///< express: joy, sadness, anger, fear, surprise, disgust, neutral
  float intensity = 1;           ///< express: 0 .. 1 (carried in hundredths)
  std::uint32_t target = 0;      ///< look_at, snub: an avatar id
  std::uint32_t duration_ms = 3000;  ///< express, look_at, snub: 0 .. 600000
  std::string sentence;          ///< facs: a FACS expression sentence; check: a script to parse; play_look: the look's name
  FaceOverride override_face;    ///< override_face
};

/// Down: the answer to a command.
struct CommandResult {
  std::uint32_t request_id = 0;
  std::string error;  ///< empty: accepted; else why not (at most 120 bytes)
};

/// Down: a piece of an avatar's package. The preview (about 1 KB) comes
/// first, the full package after it; chunks of one package arrive in order.
struct PackageChunk {
  enum class Quality : std::uint8_t { preview = 0, full = 1 };
  std::uint32_t avatar = 0;
  Quality quality = Quality::preview;
  std::uint32_t total_bytes = 0;  ///< the whole package, 1 .. kMaxPackageBytes
  std::uint32_t offset = 0;       ///< where `data` goes
  std::vector<std::uint8_t> data; ///< 1 .. kMaxChunkBytes, offset + size <= total
};

/// Up: a new downstream budget (0: the server's default).
struct SetRate {
  std::uint32_t max_bps = 0;
};

/// Up: a probe; the server answers at once with a Pong.
struct Ping {
  std::uint32_t nonce = 0;
  std::uint64_t client_time_us = 0;
};
struct Pong {
  std::uint32_t nonce = 0;
  std::uint64_t client_time_us = 0;  ///< echoed
  std::uint64_t server_time_us = 0;  ///< the server's monotonic clock (as in TimedRoomFrame)
};

/// Down, about once a second: what the server measures of this subscriber.
struct LinkStats {
  std::uint32_t target_bps = 0;   ///< what the rate control aims at now
  std::uint32_t drain_bps = 0;    ///< what actually left the server (last second)
  std::uint32_t queued_bytes = 0; ///< waiting to be written
  std::uint32_t skipped_ticks = 0;///< ticks dropped because the link was full (since the start)
};

/// Down, the last message before the server closes the connection.
enum class CloseCode : std::uint16_t {
  normal = 0,               ///< the client left
  protocol_error = 1,       ///< a malformed message
  message_too_large = 2,
  unsupported_version = 3,
  unauthorized = 4,         ///< missing, bad or expired token, or one for another room
  room_full = 5,
  rate_limited = 6,         ///< too many messages or bytes from the client
  handshake_timeout = 7,    ///< no hello in time
  idle_timeout = 8,         ///< nothing from the client in time
  shutting_down = 9,        ///< the server drains
  bad_request = 10,         ///< a well-formed hello the server cannot serve (bad name, unknown avatar)
  server_full = 11,
  avatar_being_prepared = 12,  ///< the hello's avatar is being prepared again for this server's version: try again soon
};
struct Closing {
  CloseCode code = CloseCode::normal;
  std::string reason;  ///< at most 120 bytes, for a person
};

/// Down: every avatar's seat, sent when a join or a leave laid the room out
/// again (welcome and presence carry the seats of their moment).
struct Seats {
  struct Entry {
    std::uint32_t avatar = 0;
    SeatInfo seat;
  };
  std::vector<Entry> seats;  ///< at most kMaxWelcomeAvatars
};

/// What a face attends: another avatar, the room at large (searching it,
/// no one in particular), or nobody (it looks away from everyone: a snub).
enum class AttentionTarget : std::uint8_t { nobody = 0, room = 1, avatar = 2 };

/// Down: whom faces attend, on change only; after the welcome, everyone's.
struct Attention {
  struct Entry {
    std::uint32_t avatar = 0;
    AttentionTarget target = AttentionTarget::room;
    std::uint32_t target_avatar = 0;  ///< when target is avatar
    bool operator==(const Entry&) const = default;
  };
  std::vector<Entry> entries;  ///< at most kMaxWelcomeAvatars
};

/// Down, to sessions whose hello was version 4: a face begins to say a chat
/// line. Sent before the first room frame that carries the line; a client
/// starts what it keeps in step with the line (sound) when it shows that frame.
struct Speaking {
  std::uint32_t avatar = 0;       ///< who speaks
  std::uint32_t tick = 0;         ///< the room tick whose frame is the line's first (as TimedRoomFrame::tick)
  std::uint32_t duration_ms = 0;  ///< how long the face speaks, 0 .. kMaxSpeakingMs
  std::string language;           ///< the language it is said in, is_language_code
  std::string text;               ///< the part of the line said, 1 .. 500 bytes
};

/// Down, to sessions whose hello was version 5: the action units an avatar's
/// person redefined with a face script (AU definitions), as morphs of the
/// generic face, in its vertex order. Every message holds the avatar's whole
/// set: a client replaces what it holds for the avatar by it (none: every
/// unit is the shipped one again). `version` grows by one with every change.
struct UnitMorphs {
  struct Move {
    std::uint32_t vertex = 0;                  ///< generic skin vertex, strictly increasing within a unit
    std::array<std::int16_t, 3> delta{};       ///< x, y, z at full intensity, 1/kUnitMorphStepsPerUnit model units
    bool operator==(const Move&) const = default;
  };
  struct Unit {
    std::uint8_t channel = 0;                  ///< FaceParams AU channel, strictly increasing
    std::vector<Move> moves;                   ///< at most kMaxUnitMorphMoves; none: the unit moves nothing
    bool operator==(const Unit&) const = default;
  };
  std::uint32_t avatar = 0;
  std::uint32_t version = 0;                   ///< 1 for the first redefinition, +1 each change
  std::vector<Unit> units;                     ///< at most kMaxRedefinedChannels
};

/// Down, to the connection that owns a face-lab preview only (PROTOCOL.md
/// 5.18): the part of its avatar's simulated skin displacement that the
/// action units of its frames do not explain (the residual), per skin
/// vertex of the generic face. A client adds it to the face it rebuilds
/// from the frames, so it draws the simulated surface itself. Each message
/// holds the whole residual: a vertex not listed has none.
struct PreviewSurface {
  std::uint32_t avatar = 0;
  std::vector<UnitMorphs::Move> moves;  ///< vertices strictly increasing, at most kMaxUnitMorphMoves; deltas in 1/kUnitMorphStepsPerUnit model units
  bool operator==(const PreviewSurface&) const = default;
};

/// Down, instead of a bare room frame when the hello asked for timestamps.
struct TimedRoomFrame {
  std::uint32_t tick = 0;            ///< the room's tick index
  std::uint64_t server_time_us = 0;  ///< server monotonic clock when the tick was simulated
  std::span<const std::uint8_t> room_frame;  ///< the codec room frame (a view into the message)
};

// Writers append one whole message to `out` (which they do not clear).
// Preconditions (field limits) are asserted: callers validate user input.
void write_message(const Hello& message, std::vector<std::uint8_t>& out);
void write_message(const Welcome& message, std::vector<std::uint8_t>& out);
void write_message(const Presence& message, std::vector<std::uint8_t>& out);
void write_message(const Chat& message, std::vector<std::uint8_t>& out);
void write_message(const Command& message, std::vector<std::uint8_t>& out);
void write_message(const CommandResult& message, std::vector<std::uint8_t>& out);
void write_message(const PackageChunk& message, std::vector<std::uint8_t>& out);
void write_message(const SetRate& message, std::vector<std::uint8_t>& out);
void write_message(const Ping& message, std::vector<std::uint8_t>& out);
void write_message(const Pong& message, std::vector<std::uint8_t>& out);
void write_message(const LinkStats& message, std::vector<std::uint8_t>& out);
void write_message(const Closing& message, std::vector<std::uint8_t>& out);
void write_message(const TimedRoomFrame& message, std::vector<std::uint8_t>& out);
void write_message(const Seats& message, std::vector<std::uint8_t>& out);
void write_message(const Attention& message, std::vector<std::uint8_t>& out);
void write_message(const Speaking& message, std::vector<std::uint8_t>& out);
void write_message(const UnitMorphs& message, std::vector<std::uint8_t>& out);
void write_message(const PreviewSurface& message, std::vector<std::uint8_t>& out);

// Readers parse one whole message; on error the output holds no meaning.
// A hello or welcome of version 3 or 4 reads (with the layout of its version);
// written back, each keeps its version's layout.
MessageError read_message(std::span<const std::uint8_t> bytes, Hello& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Welcome& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Presence& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Chat& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Command& message);
MessageError read_message(std::span<const std::uint8_t> bytes, CommandResult& message);
MessageError read_message(std::span<const std::uint8_t> bytes, PackageChunk& message);
MessageError read_message(std::span<const std::uint8_t> bytes, SetRate& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Ping& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Pong& message);
MessageError read_message(std::span<const std::uint8_t> bytes, LinkStats& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Closing& message);
/// `message.room_frame` views into `bytes`; the room frame itself is not
/// checked here (read_room_frame does that).
MessageError read_message(std::span<const std::uint8_t> bytes, TimedRoomFrame& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Seats& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Attention& message);
MessageError read_message(std::span<const std::uint8_t> bytes, Speaking& message);
MessageError read_message(std::span<const std::uint8_t> bytes, UnitMorphs& message);
MessageError read_message(std::span<const std::uint8_t> bytes, PreviewSurface& message);

// ---------------------------------------------------------------------------
// TCP framing: every message is preceded by its length as an unsigned LEB128
// varint of 1 .. 3 bytes (PROTOCOL.md, "Framing").

inline constexpr std::size_t kMaxLengthPrefixBytes = 3;

/// Appends the length prefix of a `message_bytes`-long message, then nothing else.
void write_length_prefix(std::size_t message_bytes, std::vector<std::uint8_t>& out);
/// Appends prefix and message.
void write_tcp_frame(std::span<const std::uint8_t> message, std::vector<std::uint8_t>& out);

/// Splits a TCP byte stream into messages. Feed it what the socket delivers;
/// take messages out with next(). Holds at most one message plus what the
/// last feed brought.
class TcpDeframer {
 public:
  /// @param[in] max_message_bytes  longer messages are an error (too_large)
  explicit TcpDeframer(std::size_t max_message_bytes);

  void feed(std::span<const std::uint8_t> bytes);
  enum class Status { message, need_more, error };
  /// The next whole message (valid until the next feed or next call), or
  /// need_more, or error (`error()` says which; the stream is unusable after it).
  Status next(std::span<const std::uint8_t>& message);
  MessageError error() const { return error_; }
  /// Bytes fed and not yet returned.
  std::size_t buffered() const { return buffer_.size() - consumed_; }

 private:
  std::size_t max_message_bytes_;
  std::vector<std::uint8_t> buffer_;
  std::size_t consumed_ = 0;
  MessageError error_ = MessageError::ok;
};

}  // namespace fw::codec
