// Session message writers (server/PROTOCOL.md, "Messages").
#include <cassert>
#include <cmath>

#include "fw/codec/face_params.hpp"
#include "message_fields.hpp"

namespace fw::codec {
namespace {

using namespace message_fields;

// Whole millimetres and ten-thousandths of a radian, clamped to what an i16 holds.
std::int16_t to_i16(float value, float scale, float limit) {
  const float v = std::isfinite(value) ? std::fmin(limit, std::fmax(-limit, value * scale)) : 0.0f;
  return static_cast<std::int16_t>(std::lround(v));
}

void write_seat(ByteWriter& w, const SeatInfo& seat) {
  w.i16_le(to_i16(seat.x_mm, 1.0f, 32767.0f));
  w.i16_le(to_i16(seat.y_mm, 1.0f, 32767.0f));
  w.i16_le(to_i16(seat.z_mm, 1.0f, 32767.0f));
  w.i16_le(to_i16(seat.facing_yaw_rad, 10000.0f, static_cast<float>(kMaxFacingTenThousandths)));
}

void write_avatar_info(ByteWriter& w, const AvatarInfo& a) {
  assert(a.id <= kMaxAvatarIdValue && a.name.size() <= kMaxDisplayNameBytes && a.asset.size() <= kMaxAssetIdBytes);
  assert(a.preview_bytes <= kMaxPackageBytes && a.full_bytes <= kMaxPackageBytes);
  w.varint(a.id);
  w.u8(a.person ? 1 : 0);
  write_string(w, a.name);
  write_string(w, a.asset);
  w.varint(a.preview_bytes);
  w.varint(a.full_bytes);
  write_seat(w, a.seat);
}

}  // namespace

void write_message(const Hello& m, std::vector<std::uint8_t>& out) {
  assert(m.room.size() <= kMaxRoomNameBytes && m.name.size() <= kMaxDisplayNameBytes);
  assert(m.avatar.size() <= kMaxAssetIdBytes && m.token.size() <= kMaxTokenBytes && m.max_bps <= kMaxBitsPerSecond);
  assert(m.avatar_key.size() <= kMaxKeyBytes && m.resume.size() <= kMaxKeyBytes);
  assert(m.protocol_version >= kOldestProtocolVersion && m.protocol_version <= kProtocolVersion);
  // A version-3 hello has no language field: one set there would be lost.
  assert(m.protocol_version >= kFirstSpeakingVersion ? (m.language.empty() || is_language_code(m.language))
                                                     : m.language.empty());
  ByteWriter w(out);
  w.u8(first_byte(MessageType::hello));
  w.u16_le(m.protocol_version);
  w.u8(static_cast<std::uint8_t>((m.timestamps ? 1 : 0) | (m.no_packages ? 2 : 0) | (m.own_package ? 4 : 0) |
                                (m.preview ? 8 : 0)));
  w.varint(m.max_bps);
  write_string(w, m.room);
  write_string(w, m.name);
  write_string(w, m.avatar);
  write_string(w, m.token);
  write_string(w, m.avatar_key);
  write_string(w, m.resume);
  if (m.protocol_version >= kFirstSpeakingVersion) write_string(w, m.language);
}

void write_message(const Welcome& m, std::vector<std::uint8_t>& out) {
  assert(m.you <= kMaxAvatarIdValue && m.room.size() <= kMaxRoomNameBytes && m.tick_hz > 0);
  assert(m.avatars.size() <= kMaxWelcomeAvatars && m.max_bps <= kMaxBitsPerSecond && m.resume.size() <= kMaxKeyBytes);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::welcome));
  w.u16_le(m.protocol_version);
  w.varint(m.you);
  write_string(w, m.room);
  w.u8(m.tick_hz);
  w.varint(m.max_bps);
  w.varint(static_cast<std::uint32_t>(m.avatars.size()));
  for (const AvatarInfo& a : m.avatars) write_avatar_info(w, a);
  write_string(w, m.resume);
}

void write_message(const Presence& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u8(first_byte(MessageType::presence));
  w.u8(static_cast<std::uint8_t>(m.change));
  write_avatar_info(w, m.avatar);
}

void write_message(const Chat& m, std::vector<std::uint8_t>& out) {
  assert(m.from <= kMaxAvatarIdValue && m.text.size() <= kMaxChatBytes);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::chat));
  w.varint(m.from);
  write_string(w, m.text);
}

void write_message(const Command& m, std::vector<std::uint8_t>& out) {
  assert(m.duration_ms <= kMaxCommandMs);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::command));
  w.varint(m.request_id);
  w.u8(static_cast<std::uint8_t>(m.kind));
  switch (m.kind) {
    case Command::Kind::express: {
      assert(m.emotion.size() <= kMaxEmotionBytes);
      write_string(w, m.emotion);
      const float clamped = std::isfinite(m.intensity) ? std::fmin(1.0f, std::fmax(0.0f, m.intensity)) : 0.0f;
      w.u8(static_cast<std::uint8_t>(std::lround(clamped * 100.0f)));
      w.varint(m.duration_ms);
      break;
    }
    case Command::Kind::look_at:
    case Command::Kind::snub:
      assert(m.target <= kMaxAvatarIdValue);
      w.varint(m.target);
      w.varint(m.duration_ms);
      break;
    case Command::Kind::facs:
    case Command::Kind::check:
      assert(m.sentence.size() <= kMaxSentenceBytes);
      write_string(w, m.sentence);
      break;
    case Command::Kind::play_look:
      assert(!m.sentence.empty() && m.sentence.size() <= kMaxLookNameBytes);
      write_string(w, m.sentence);
      break;
    case Command::Kind::override_face:
      assert(m.override_face.side <= 2);
      w.u8(static_cast<std::uint8_t>(m.override_face.part));
      w.u8(m.override_face.index);
      w.u8(m.override_face.side);
      w.i16_le(m.override_face.value);
      break;
  }
}

void write_message(const CommandResult& m, std::vector<std::uint8_t>& out) {
  assert(m.error.size() <= kMaxReasonBytes);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::command_result));
  w.varint(m.request_id);
  write_string(w, m.error);
}

void write_message(const PackageChunk& m, std::vector<std::uint8_t>& out) {
  assert(m.avatar <= kMaxAvatarIdValue && m.total_bytes >= 1 && m.total_bytes <= kMaxPackageBytes);
  assert(!m.data.empty() && m.data.size() <= kMaxChunkBytes && m.offset + m.data.size() <= m.total_bytes);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::package_chunk));
  w.varint(m.avatar);
  w.u8(static_cast<std::uint8_t>(m.quality));
  w.varint(m.total_bytes);
  w.varint(m.offset);
  w.bytes(m.data);
}

void write_message(const SetRate& m, std::vector<std::uint8_t>& out) {
  assert(m.max_bps <= kMaxBitsPerSecond);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::set_rate));
  w.varint(m.max_bps);
}

void write_message(const Ping& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u8(first_byte(MessageType::ping));
  write_u32_le(w, m.nonce);
  write_u64_le(w, m.client_time_us);
}

void write_message(const Pong& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u8(first_byte(MessageType::pong));
  write_u32_le(w, m.nonce);
  write_u64_le(w, m.client_time_us);
  write_u64_le(w, m.server_time_us);
}

void write_message(const LinkStats& m, std::vector<std::uint8_t>& out) {
  ByteWriter w(out);
  w.u8(first_byte(MessageType::link_stats));
  w.varint(m.target_bps);
  w.varint(m.drain_bps);
  w.varint(m.queued_bytes);
  w.varint(m.skipped_ticks);
}

void write_message(const Closing& m, std::vector<std::uint8_t>& out) {
  assert(m.reason.size() <= kMaxReasonBytes);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::closing));
  w.u16_le(static_cast<std::uint16_t>(m.code));
  write_string(w, m.reason);
}

void write_message(const TimedRoomFrame& m, std::vector<std::uint8_t>& out) {
  assert(!m.room_frame.empty());
  ByteWriter w(out);
  w.u8(first_byte(MessageType::timed_room_frame));
  w.varint(m.tick);
  write_u64_le(w, m.server_time_us);
  w.bytes(m.room_frame);
}

void write_message(const Seats& m, std::vector<std::uint8_t>& out) {
  assert(m.seats.size() <= kMaxWelcomeAvatars);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::seats));
  w.varint(static_cast<std::uint32_t>(m.seats.size()));
  for (const Seats::Entry& e : m.seats) {
    assert(e.avatar <= kMaxAvatarIdValue);
    w.varint(e.avatar);
    write_seat(w, e.seat);
  }
}

void write_message(const Attention& m, std::vector<std::uint8_t>& out) {
  assert(m.entries.size() <= kMaxWelcomeAvatars);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::attention));
  w.varint(static_cast<std::uint32_t>(m.entries.size()));
  for (const Attention::Entry& e : m.entries) {
    assert(e.avatar <= kMaxAvatarIdValue && e.target_avatar <= kMaxAvatarIdValue);
    w.varint(e.avatar);
    w.u8(static_cast<std::uint8_t>(e.target));
    if (e.target == AttentionTarget::avatar) w.varint(e.target_avatar);
  }
}

void write_message(const Speaking& m, std::vector<std::uint8_t>& out) {
  assert(m.avatar <= kMaxAvatarIdValue && m.duration_ms <= kMaxSpeakingMs && is_language_code(m.language));
  assert(!m.text.empty() && m.text.size() <= kMaxChatBytes);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::speaking));
  w.varint(m.avatar);
  w.varint(m.tick);
  w.varint(m.duration_ms);
  write_string(w, m.language);
  write_string(w, m.text);
}

}  // namespace fw::codec

namespace fw::codec {

namespace {

void write_moves(ByteWriter& w, const std::vector<UnitMorphs::Move>& moves) {
  assert(moves.size() <= kMaxUnitMorphMoves);
  w.varint(static_cast<std::uint32_t>(moves.size()));
  for (const UnitMorphs::Move& move : moves) {
    assert(move.vertex < kMaxUnitMorphMoves);
    w.varint(move.vertex);
    for (const std::int16_t d : move.delta) w.i16_le(d);
  }
}

}  // namespace

void write_message(const UnitMorphs& m, std::vector<std::uint8_t>& out) {
  assert(m.avatar <= kMaxAvatarIdValue && m.units.size() <= kMaxRedefinedChannels);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::unit_morphs));
  w.varint(m.avatar);
  w.varint(m.version);
  w.u8(static_cast<std::uint8_t>(m.units.size()));
  for (const UnitMorphs::Unit& unit : m.units) {
    assert(unit.channel < kAuChannelCount && unit.moves.size() <= kMaxUnitMorphMoves);
    w.u8(unit.channel);
    write_moves(w, unit.moves);
  }
}

void write_message(const PreviewSurface& m, std::vector<std::uint8_t>& out) {
  assert(m.avatar <= kMaxAvatarIdValue);
  ByteWriter w(out);
  w.u8(first_byte(MessageType::preview_surface));
  w.varint(m.avatar);
  write_moves(w, m.moves);
}

}  // namespace fw::codec
