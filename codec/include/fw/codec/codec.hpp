#pragma once
// The facewire codec: FaceParams <-> a compact, versioned bitstream
// (codec/FORMAT.md is the normative description; this header is its C++ API).
//
// One Encoder per subscriber stream of one avatar: it is offered the face of
// every tick (30 Hz) and returns a frame only when the viewer would otherwise
// see a difference, staying under its target bit rate. One Decoder per
// avatar on the receiving side. Room frames bundle the frames of several
// avatars into one message. Everything here needs the C++ standard library
// only.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "fw/codec/face_params.hpp"

namespace fw::codec {

/// Bitstream version carried in the high nibble of every frame's first byte.
/// A change to any golden vector (tests/vectors/codec) is a change of version.
/// Version 2 added the corrective channels (FaceParams schema 2); a decoder
/// refuses version-1 messages (unsupported_version) rather than guess.
inline constexpr std::uint8_t kFormatVersion = 2;

/// The low nibble of every frame's first byte.
enum class FrameType : std::uint8_t {
  stream_header = 0,   ///< once per connection: magic, schema, channel table, options
  key = 1,             ///< absolute values of every channel; resets the adaptive models
  predicted = 2,       ///< changes against the decoder's own reconstruction
  room = 3,            ///< several avatars' key/predicted frames, each with its avatar id
  resync_request = 4,  ///< upstream: "send me a key frame for these avatars"
};

/// Why a frame was refused. The numeric values are part of the format
/// (FORMAT.md, "Error codes") and never change; new codes only get new numbers.
enum class DecodeError : std::uint8_t {
  ok = 0,
  empty_frame = 1,             ///< zero bytes
  unsupported_version = 2,     ///< first byte's high nibble is not kFormatVersion
  unknown_frame_type = 3,      ///< first byte's low nibble is not a FrameType
  wrong_frame_type = 4,        ///< a valid type, but not one this call accepts
  bad_magic = 5,               ///< stream header without "FWFP"
  unsupported_schema = 6,      ///< stream header for another FaceParams schema
  channel_table_mismatch = 7,  ///< stream header's channel table differs from this schema's
  bad_stream_options = 8,      ///< reserved flag bits set, or a tick rate of 0
  truncated = 9,               ///< a byte-aligned field runs past the end of the frame
  awaiting_key_frame = 10,     ///< predicted frame before any key frame, or after a gap
  sequence_gap = 11,           ///< loss-tolerant stream: frames were lost (face frozen until a key frame)
  stale_frame = 12,            ///< loss-tolerant stream: a duplicate or late frame (ignored)
  value_out_of_range = 13,     ///< a decoded number lies outside what the format allows
  check_failed = 14,           ///< the frame's check bits do not match: corrupt or cut short
  too_many_avatars = 15,       ///< room frame or resync request over kMaxRoomAvatars entries
  duplicate_avatar = 16,       ///< room frame names one avatar twice
  frame_too_large = 17,        ///< over kMaxFrameBytes (or kMaxRoomFrameBytes for a room frame)
  trailing_bytes = 18,         ///< bytes after the end of a byte-aligned message
};

/// A sentence for a person: what was wrong with the frame.
std::string_view describe(DecodeError error);

/// Limits every decoder enforces (FORMAT.md, "Limits").
inline constexpr std::size_t kMaxFrameBytes = 1024;        ///< one avatar's key or predicted frame
inline constexpr std::size_t kMaxRoomAvatars = 64;         ///< entries in a room frame or resync request
inline constexpr std::size_t kMaxRoomFrameBytes = 64 * 1024;
inline constexpr std::uint32_t kMaxAvatarId = (1u << 21) - 1;  ///< ids 0 .. 63 take one byte in a room frame

// ---------------------------------------------------------------------------
// Channels: FaceParams as 53 integers on a fixed grid.

/// Number of coded channels: 29 AUs, 3 head rotations, 3 head translations,
/// 4 eye rotations, 2 lids, 5 blush regions, pallor, 6 corrective weights
/// (in FaceParams order).
inline constexpr std::size_t kChannelCount =
    kAuChannelCount + 3 + 3 + 4 + 2 + kColourRegionCount + 1 + kCorrectiveCount;

/// Channel groups: each has one "unchanged" flag per predicted frame and one
/// quantiser shift per quality level.
enum class ChannelGroup : std::uint8_t {
  action_units,
  head_rotation,
  head_translation,
  eyes,
  lids,
  colour,
  correctives,
  count
};
inline constexpr std::size_t kChannelGroupCount = static_cast<std::size_t>(ChannelGroup::count);

struct ChannelInfo {
  std::string_view name;  ///< e.g. "au12_left", "head_yaw", "eye_right_pitch"
  ChannelGroup group;
  float step;             ///< one grid step in the field's unit (rad, mm, or intensity)
  std::int32_t min_q;     ///< smallest value on the grid (value = q * step)
  std::int32_t max_q;     ///< largest value on the grid
  std::int8_t partner;    ///< the left-side channel a right-side one is predicted from, or -1
  /// The channel added to this field before coding, or -1: an eye is coded
  /// as its direction in the world (eye + head rotation), which holds still
  /// while the head turns and the eye counter-rotates.
  std::int8_t base;
};

/// The channel table of FaceParams schema 2, in FaceParams field order.
/// min_q/max_q are the field's range; a channel with a base is coded over
/// the sum of both ranges (FORMAT.md, "Channels").
const std::array<ChannelInfo, kChannelCount>& channel_table();

/// The FaceParams field that carries channel `channel` (0 .. kChannelCount-1).
float channel_value(const FaceParams& params, std::size_t channel);
void set_channel_value(FaceParams& params, std::size_t channel, float value);

/// The exact decoded face: one integer per channel (value = q * step).
using QuantisedParams = std::array<std::int32_t, kChannelCount>;

/// Nearest grid value of every field, clamped to the channel's range; NaN
/// counts as 0 (the rest pose).
QuantisedParams quantise(const FaceParams& params);
/// The FaceParams a decoder hands to the renderer: float(q) * step per field.
FaceParams dequantise(const QuantisedParams& q);

// ---------------------------------------------------------------------------
// Stream header.

struct StreamOptions {
  /// Frames carry a sequence number; the decoder detects lost and late
  /// frames and freezes the face until the next key frame.
  bool loss_tolerant = false;
  /// Ticks per second of the sender's clock (frames are stamped in ticks).
  std::uint8_t tick_rate_hz = 30;
  /// A channel's velocity moves it for at most this many ticks after its
  /// last update; 0 turns extrapolation off (the face holds between frames).
  std::uint8_t max_extrapolation_ticks = 32;
};

/// The stream header message (FrameType::stream_header) for `options`.
std::vector<std::uint8_t> write_stream_header(const StreamOptions& options);
/// Parses a stream header; on success fills `options`.
DecodeError read_stream_header(std::span<const std::uint8_t> bytes, StreamOptions& options);

// ---------------------------------------------------------------------------
// Encoder.

/// The error per channel, in the field's own unit (intensity, rad, mm), at
/// which a viewer starts to see a difference: 0.35 mm at the vertex the
/// channel moves most (AUs: its largest displacement at intensity 1, from
/// the generic face's action-unit table; head rotation: 126 mm from the neck
/// pivot to the farthest vertex; lids: 10 mm of travel), 0.4 degree of gaze
/// for each eye's pair of channels (yaw and pitch together), 1/32 of full
/// blush or pallor. Estimates for a face with a 63 mm inter-ocular distance
/// (FORMAT.md, "Encoder"); a server that knows the face's morphs should pass
/// its own (visible_mm / largest displacement of each AU's morph).
std::array<float, kChannelCount> default_visible_error();

struct EncoderOptions {
  StreamOptions stream;
  /// Bits per second this stream may use, every header byte included
  /// (FORMAT.md counts frames only; a room frame adds its entry bytes).
  double target_bps = 500;
  /// Bytes a container adds to every frame, charged to the budget: about 2
  /// in a room frame (the entry's avatar id and length, a share of the room
  /// frame's first byte), 0 when frames travel as messages of their own.
  double container_bytes_per_frame = 0;
  /// What each channel may be off by at quality level 3 before the viewer
  /// would notice; level l allows kLevelFactor[l] times as much.
  std::array<float, kChannelCount> visible_error = default_visible_error();
  /// Eye contact matters most: whatever the level, neither eye's gaze is
  /// allowed further off than this (radians; 0.45 degree) while the budget
  /// lets frames out.
  float max_gaze_error_rad = 0.45f * 3.14159265f / 180.0f;
  /// Quality levels the rate control may use (0 finest .. kMaxQualityLevel
  /// coarsest). Equal values pin the level. Levels under 3 hold errors
  /// below what a viewer sees, at a cost in bits; allow them for recordings.
  int min_level = 3;
  int max_level = 7;
  /// Loss-tolerant streams only: the longest wait between key frames, in
  /// ticks. The rate control uses a shorter interval when the budget allows.
  int max_key_interval_ticks = 300;
  /// Loss-tolerant streams only: a frame goes out at least this often, so a
  /// lost frame is noticed within this many ticks even when nothing moves.
  /// Keep it at or below stream.max_extrapolation_ticks.
  int heartbeat_ticks = 15;
  /// A face that moves at all is sent at least this often, in ticks, even
  /// while every channel stays within its tolerance of the prediction: its
  /// smallest changes then arrive at this rate instead of waiting to add up.
  /// 0: frames only when the viewer would see a difference (the least bits).
  int refresh_ticks = 0;
  /// A refresh goes out only while the rate control's bucket stays under
  /// this share of its capacity (1/3: a second of budget), so that it
  /// spends what is spare and never delays a frame the viewer would miss;
  /// 1 lets refreshes use the whole budget (more frames, coarser gaze).
  double refresh_bucket_share = 1.0 / 3.0;
};

inline constexpr int kMaxQualityLevel = 7;
/// How much error each quality level allows, as a multiple of visible_error.
inline constexpr std::array<double, kMaxQualityLevel + 1> kLevelFactor = {0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0};

/// What the encoder did with the last offered face (for tests and benchmarks).
struct EncoderStats {
  std::uint32_t tick = 0;           ///< index of the last offered tick (0 for the first)
  FrameType last_type = FrameType::key;
  bool sent = false;                ///< whether the last offered tick produced a frame
  std::size_t last_bytes = 0;       ///< size of that frame
  int level = 0;                    ///< quality level now in force
  int key_interval_ticks = 0;       ///< 0 when key frames are sent on demand only
  double bucket_bits = 0;           ///< leaky-bucket fill after the last tick
  double bucket_capacity_bits = 0;
  std::uint64_t frames_sent = 0;
  std::uint64_t bytes_sent = 0;
};

/// One avatar's face, tick by tick, as its encoders see it: the coded
/// channels (grid steps) of this tick and the two before. A server encodes
/// each face once per viewer, and this part of the work is the same for
/// every viewer: worked out once per face per tick, it is shared by all of
/// them (Encoder::encode(const FaceSource&, ...)).
class FaceSource {
 public:
  /// This tick's face: call once per tick, every tick, before its encoders.
  void offer(const FaceParams& params);
  /// Ticks offered so far.
  std::uint64_t ticks() const { return ticks_; }

 private:
  friend class Encoder;
  std::array<double, kChannelCount> x_{};
  std::array<double, kChannelCount> previous_{};
  std::array<double, kChannelCount> before_previous_{};
  std::uint64_t ticks_ = 0;
};

class Encoder {
 public:
  explicit Encoder(const EncoderOptions& options);
  ~Encoder();
  Encoder(Encoder&&) noexcept;
  Encoder& operator=(Encoder&&) noexcept;

  /// Offers the face of the next tick (call once per tick, every tick).
  /// @param[in]  params  this tick's face
  /// @param[out] frame   cleared, then the frame to send (a key or predicted
  ///                     frame); left empty when this tick is skipped
  /// @return whether a frame was produced
  bool encode(const FaceParams& params, std::vector<std::uint8_t>& frame);
  /// Offers the face of a tick that carries no frame of this stream (its
  /// sender bundles frames on fewer ticks, or its link is congested): the
  /// clock, the budget and the motion estimate move on as if the tick had
  /// been skipped for lack of budget. Call it instead of encode().
  void hold(const FaceParams& params);
  /// The same from a face offered to `source` this tick: frames byte for
  /// byte as encode(params) and hold(params) give, provided the encoder was
  /// offered each of the source's last two ticks (its motion estimate reads
  /// the source's history; a stream offered the face as FaceParams keeps its
  /// own). Use one kind of offer or the other for an encoder.
  bool encode(const FaceSource& source, std::vector<std::uint8_t>& frame);
  void hold(const FaceSource& source);

  /// Changes the bit budget from the next tick on.
  void set_target_bps(double bits_per_second);
  /// The next frame is a key frame (sent as soon as the budget allows): after
  /// a resync request, or when a subscriber joins.
  void force_key_frame();
  /// What the decoder shows at the last offered tick, exactly.
  QuantisedParams reconstruction() const;
  EncoderStats stats() const;
  const EncoderOptions& options() const;

 private:
  bool encode_tick(const std::array<double, kChannelCount>& x, const FaceSource* source,
                   std::vector<std::uint8_t>& frame, bool may_send);
  struct State;
  std::unique_ptr<State> state_;
};

// ---------------------------------------------------------------------------
// Decoder.

class Decoder {
 public:
  /// A decoder for one avatar's frames; `options` come from the stream header.
  explicit Decoder(const StreamOptions& options = {});
  ~Decoder();
  Decoder(Decoder&&) noexcept;
  Decoder& operator=(Decoder&&) noexcept;

  /// Decodes one key or predicted frame. On any error the face stays what
  /// it was (frozen after a sequence gap) and the error says why.
  DecodeError decode(std::span<const std::uint8_t> frame);

  /// The face at `ticks_after` ticks after the last decoded frame: channels
  /// keep moving with their velocity for at most max_extrapolation_ticks.
  QuantisedParams quantised(std::uint32_t ticks_after = 0) const;
  FaceParams face(std::uint32_t ticks_after = 0) const;

  /// Whether a key frame is needed before predicted frames are accepted
  /// (before the first key frame, and after a sequence gap): the caller
  /// should send a resync request.
  bool needs_key_frame() const;
  /// Sum of the tick deltas of all decoded frames since this decoder started.
  std::uint64_t tick() const;
  /// Frames decoded without error.
  std::uint64_t frames_decoded() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// ---------------------------------------------------------------------------
// Room frames and resync requests.

struct RoomEntry {
  std::uint32_t avatar_id = 0;          ///< 0 .. kMaxAvatarId
  std::span<const std::uint8_t> frame;  ///< a key or predicted frame (a view, not a copy)
};

/// Appends a room frame carrying `entries` (1 .. kMaxRoomAvatars, distinct ids,
/// each frame 1 .. kMaxFrameBytes) to `out`. Preconditions are asserted.
void write_room_frame(std::span<const RoomEntry> entries, std::vector<std::uint8_t>& out);
/// Splits a room frame. `entries` is cleared and gets views into `bytes`;
/// it never grows past kMaxRoomAvatars. Entry frames are not decoded here.
DecodeError read_room_frame(std::span<const std::uint8_t> bytes, std::vector<RoomEntry>& entries);

/// Appends a resync request for `avatar_ids` (0 .. kMaxRoomAvatars ids).
void write_resync_request(std::span<const std::uint32_t> avatar_ids, std::vector<std::uint8_t>& out);
DecodeError read_resync_request(std::span<const std::uint8_t> bytes, std::vector<std::uint32_t>& avatar_ids);

/// Decoders for every avatar of one room stream, created when an avatar's
/// first frame arrives (at most kMaxRoomAvatars of them).
class RoomDecoder {
 public:
  explicit RoomDecoder(const StreamOptions& options = {});

  struct Result {
    DecodeError error = DecodeError::ok;  ///< of the room frame itself
    /// Per entry, in frame order: the avatar and what its decoder said.
    std::vector<std::pair<std::uint32_t, DecodeError>> avatars;
  };
  /// Decodes a room frame into the avatars' decoders.
  Result decode(std::span<const std::uint8_t> room_frame);
  /// The avatar's decoder, or nullptr if none of its frames arrived yet.
  const Decoder* avatar(std::uint32_t avatar_id) const;
  /// Drops an avatar that left the room.
  void remove(std::uint32_t avatar_id);
  /// Avatars whose decoder waits for a key frame (for a resync request).
  std::vector<std::uint32_t> needing_key_frames() const;
  std::size_t size() const { return decoders_.size(); }

 private:
  StreamOptions options_;
  std::vector<std::pair<std::uint32_t, Decoder>> decoders_;
};

}  // namespace fw::codec
