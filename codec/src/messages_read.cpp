// Session message readers (server/PROTOCOL.md, "Messages"). Each checks the
// first byte and the size limit, reads its fields through a ByteReader whose
// error flag sticks, then checks once that nothing was cut and nothing follows.
#include "fw/codec/face_params.hpp"
#include "message_fields.hpp"

namespace fw::codec {
namespace {

using namespace message_fields;

/// The result of a reader whose fields were read: the first field error,
/// else a cut, else trailing bytes.
MessageError finish(const ByteReader& r, MessageError error) {
  if (error != MessageError::ok) return error;
  if (r.failed()) return failure_of(r);
  if (r.remaining() != 0) return MessageError::trailing_bytes;
  return MessageError::ok;
}

/// Versions 3 and 4 share the welcome's layout and the hello's first fields.
bool is_readable_version(std::uint16_t version) {
  return version >= kOldestProtocolVersion && version <= kProtocolVersion;
}

void fail(MessageError& error, MessageError why) {
  if (error == MessageError::ok) error = why;
}

std::uint32_t read_bounded(ByteReader& r, std::size_t max_varint_bytes, std::uint32_t max, MessageError& error) {
  const std::uint32_t value = r.varint(max_varint_bytes);
  if (!r.failed() && value > max) fail(error, MessageError::value_out_of_range);
  return value;
}

void read_seat(ByteReader& r, SeatInfo& seat, MessageError& error) {
  seat.x_mm = r.i16_le();
  seat.y_mm = r.i16_le();
  seat.z_mm = r.i16_le();
  const std::int16_t facing = r.i16_le();
  if (!r.failed() && (facing > kMaxFacingTenThousandths || facing < -kMaxFacingTenThousandths))
    fail(error, MessageError::value_out_of_range);
  seat.facing_yaw_rad = static_cast<float>(facing) / 10000.0f;
}

/// A list's count; too_many_entries past kMaxWelcomeAvatars.
std::uint32_t read_count(ByteReader& r, MessageError& error) {
  const std::uint32_t count = r.varint(2);
  if (!r.failed() && count > kMaxWelcomeAvatars) fail(error, MessageError::too_many_entries);
  return count;
}

void read_avatar_info(ByteReader& r, AvatarInfo& a, MessageError& error) {
  a.id = read_bounded(r, 3, kMaxAvatarIdValue, error);
  const std::uint8_t flags = r.u8();
  if (!r.failed() && (flags & ~1u) != 0) fail(error, MessageError::bad_flags);
  a.person = (flags & 1u) != 0;
  read_string(r, kMaxDisplayNameBytes, a.name, error);
  read_string(r, kMaxAssetIdBytes, a.asset, error);
  a.preview_bytes = read_bounded(r, 4, kMaxPackageBytes, error);
  a.full_bytes = read_bounded(r, 4, kMaxPackageBytes, error);
  read_seat(r, a.seat, error);
}

}  // namespace

MessageError read_message(std::span<const std::uint8_t> bytes, Hello& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::hello, kMaxUpstreamMessageBytes); e != MessageError::ok)
    return e;
  m.protocol_version = r.u16_le();
  if (r.failed()) return failure_of(r);
  // Another version may lay out the rest differently: stop here.
  if (!is_readable_version(m.protocol_version)) return MessageError::unsupported_version;
  MessageError error = MessageError::ok;
  const std::uint8_t flags = r.u8();
  if (!r.failed() && (flags & ~15u) != 0) fail(error, MessageError::bad_flags);
  m.timestamps = (flags & 1u) != 0;
  m.no_packages = (flags & 2u) != 0;
  m.own_package = (flags & 4u) != 0;
  m.preview = (flags & 8u) != 0;
  m.max_bps = read_bounded(r, 4, kMaxBitsPerSecond, error);
  read_string(r, kMaxRoomNameBytes, m.room, error);
  read_string(r, kMaxDisplayNameBytes, m.name, error);
  read_string(r, kMaxAssetIdBytes, m.avatar, error);
  read_string(r, kMaxTokenBytes, m.token, error);
  read_string(r, kMaxKeyBytes, m.avatar_key, error);
  read_string(r, kMaxKeyBytes, m.resume, error);
  m.language.clear();
  if (m.protocol_version >= kFirstSpeakingVersion) read_language(r, m.language, error, /*may_be_empty=*/true);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Welcome& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::welcome, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  m.protocol_version = r.u16_le();
  if (r.failed()) return failure_of(r);
  if (!is_readable_version(m.protocol_version)) return MessageError::unsupported_version;
  MessageError error = MessageError::ok;
  m.you = read_bounded(r, 3, kMaxAvatarIdValue, error);
  read_string(r, kMaxRoomNameBytes, m.room, error);
  m.tick_hz = r.u8();
  if (!r.failed() && m.tick_hz == 0) fail(error, MessageError::value_out_of_range);
  m.max_bps = read_bounded(r, 4, kMaxBitsPerSecond, error);
  const std::uint32_t count = read_count(r, error);
  m.avatars.clear();
  for (std::uint32_t i = 0; i < count && !r.failed() && error == MessageError::ok; ++i)
    read_avatar_info(r, m.avatars.emplace_back(), error);
  read_string(r, kMaxKeyBytes, m.resume, error);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Presence& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::presence, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  const std::uint8_t change = r.u8();
  if (!r.failed() && change > 1) fail(error, MessageError::value_out_of_range);
  m.change = static_cast<Presence::Change>(change);
  read_avatar_info(r, m.avatar, error);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Chat& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::chat, kMaxDownstreamMessageBytes); e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.from = read_bounded(r, 3, kMaxAvatarIdValue, error);
  read_string(r, kMaxChatBytes, m.text, error);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Command& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::command, kMaxUpstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.request_id = r.varint(5);
  const std::uint8_t kind = r.u8();
  if (r.failed()) return failure_of(r);
  if (kind > static_cast<std::uint8_t>(Command::Kind::play_look)) return MessageError::value_out_of_range;
  m.kind = static_cast<Command::Kind>(kind);
  m.emotion.clear();
  m.sentence.clear();
  m.override_face = {};
  switch (m.kind) {
    case Command::Kind::express: {
      read_string(r, kMaxEmotionBytes, m.emotion, error);
      const std::uint8_t percent = r.u8();
      if (!r.failed() && percent > 100) fail(error, MessageError::value_out_of_range);
      m.intensity = static_cast<float>(percent) / 100.0f;
      m.duration_ms = read_bounded(r, 3, kMaxCommandMs, error);
      break;
    }
    case Command::Kind::look_at:
    case Command::Kind::snub:
      m.target = read_bounded(r, 3, kMaxAvatarIdValue, error);
      m.duration_ms = read_bounded(r, 3, kMaxCommandMs, error);
      break;
    case Command::Kind::facs:
    case Command::Kind::check:
      read_string(r, kMaxSentenceBytes, m.sentence, error, /*allow_layout=*/true);
      break;
    case Command::Kind::play_look:
      read_string(r, kMaxLookNameBytes, m.sentence, error);
      if (m.sentence.empty()) fail(error, MessageError::value_out_of_range);
      break;
    case Command::Kind::override_face: {
      const std::uint8_t part = r.u8();
      m.override_face.index = r.u8();
      m.override_face.side = r.u8();
      m.override_face.value = r.i16_le();
      if (!r.failed() && (part > kLastOverridePart || m.override_face.side > 2))
        fail(error, MessageError::value_out_of_range);
      m.override_face.part = static_cast<OverridePart>(part);
      break;
    }
  }
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, CommandResult& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::command_result, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.request_id = r.varint(5);
  read_string(r, kMaxReasonBytes, m.error, error);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, PackageChunk& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::package_chunk, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.avatar = read_bounded(r, 3, kMaxAvatarIdValue, error);
  const std::uint8_t quality = r.u8();
  if (!r.failed() && quality > 1) fail(error, MessageError::value_out_of_range);
  m.quality = static_cast<PackageChunk::Quality>(quality);
  m.total_bytes = read_bounded(r, 4, kMaxPackageBytes, error);
  m.offset = r.varint(4);
  if (r.failed()) return failure_of(r);
  if (error != MessageError::ok) return error;
  const std::size_t size = r.remaining();
  if (m.total_bytes == 0 || size == 0 || size > kMaxChunkBytes ||
      static_cast<std::uint64_t>(m.offset) + size > m.total_bytes)
    return MessageError::value_out_of_range;
  const auto data = r.bytes(size);
  m.data.assign(data.begin(), data.end());
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, SetRate& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::set_rate, kMaxUpstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.max_bps = read_bounded(r, 4, kMaxBitsPerSecond, error);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Ping& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::ping, kMaxUpstreamMessageBytes); e != MessageError::ok)
    return e;
  m.nonce = read_u32_le(r);
  m.client_time_us = read_u64_le(r);
  return finish(r, MessageError::ok);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Pong& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::pong, kMaxDownstreamMessageBytes); e != MessageError::ok)
    return e;
  m.nonce = read_u32_le(r);
  m.client_time_us = read_u64_le(r);
  m.server_time_us = read_u64_le(r);
  return finish(r, MessageError::ok);
}

MessageError read_message(std::span<const std::uint8_t> bytes, LinkStats& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::link_stats, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  m.target_bps = r.varint(5);
  m.drain_bps = r.varint(5);
  m.queued_bytes = r.varint(5);
  m.skipped_ticks = r.varint(5);
  return finish(r, MessageError::ok);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Closing& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::closing, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.code = static_cast<CloseCode>(r.u16_le());  // unknown codes pass: a newer server may add some
  read_string(r, kMaxReasonBytes, m.reason, error);
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, TimedRoomFrame& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::timed_room_frame, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  m.tick = r.varint(5);
  m.server_time_us = read_u64_le(r);
  if (r.failed()) return failure_of(r);
  if (r.remaining() == 0) return MessageError::truncated;
  m.room_frame = r.bytes(r.remaining());
  return MessageError::ok;
}

MessageError read_message(std::span<const std::uint8_t> bytes, Seats& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::seats, kMaxDownstreamMessageBytes); e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  const std::uint32_t count = read_count(r, error);
  m.seats.clear();
  for (std::uint32_t i = 0; i < count && !r.failed() && error == MessageError::ok; ++i) {
    Seats::Entry& entry = m.seats.emplace_back();
    entry.avatar = read_bounded(r, 3, kMaxAvatarIdValue, error);
    read_seat(r, entry.seat, error);
  }
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Attention& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::attention, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  const std::uint32_t count = read_count(r, error);
  m.entries.clear();
  for (std::uint32_t i = 0; i < count && !r.failed() && error == MessageError::ok; ++i) {
    Attention::Entry& entry = m.entries.emplace_back();
    entry.avatar = read_bounded(r, 3, kMaxAvatarIdValue, error);
    const std::uint8_t target = r.u8();
    if (!r.failed() && target > static_cast<std::uint8_t>(AttentionTarget::avatar))
      fail(error, MessageError::value_out_of_range);
    entry.target = static_cast<AttentionTarget>(target);
    entry.target_avatar = entry.target == AttentionTarget::avatar ? read_bounded(r, 3, kMaxAvatarIdValue, error) : 0;
  }
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, Speaking& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::speaking, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.avatar = read_bounded(r, 3, kMaxAvatarIdValue, error);
  m.tick = r.varint(5);
  m.duration_ms = read_bounded(r, 3, kMaxSpeakingMs, error);
  read_language(r, m.language, error, /*may_be_empty=*/false);
  read_string(r, kMaxChatBytes, m.text, error);
  if (!r.failed() && error == MessageError::ok && m.text.empty()) fail(error, MessageError::value_out_of_range);
  return finish(r, error);
}

}  // namespace fw::codec

namespace fw::codec {

namespace {

// A count, then moves of skin vertices strictly increasing (a unit morph's,
// a preview surface's), so a vertex is never given twice.
void read_moves(ByteReader& r, std::vector<UnitMorphs::Move>& out, MessageError& error) {
  out.clear();
  const std::uint32_t moves = r.varint(2);
  if (!r.failed() && moves > kMaxUnitMorphMoves) fail(error, MessageError::too_many_entries);
  for (std::uint32_t k = 0; k < moves && !r.failed() && error == MessageError::ok; ++k) {
    UnitMorphs::Move& move = out.emplace_back();
    move.vertex = read_bounded(r, 2, kMaxUnitMorphMoves - 1, error);
    if (!r.failed() && k > 0 && move.vertex <= out[k - 1].vertex) fail(error, MessageError::value_out_of_range);
    for (std::int16_t& d : move.delta) d = r.i16_le();
  }
}

}  // namespace

// Channels and vertices strictly increase, so a unit or a vertex is never
// given twice and the message has one reading.
MessageError read_message(std::span<const std::uint8_t> bytes, UnitMorphs& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::unit_morphs, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.avatar = read_bounded(r, 3, kMaxAvatarIdValue, error);
  m.version = r.varint(5);
  const std::uint8_t count = r.u8();
  if (!r.failed() && count > kMaxRedefinedChannels) fail(error, MessageError::too_many_entries);
  m.units.clear();
  for (std::uint32_t i = 0; i < count && !r.failed() && error == MessageError::ok; ++i) {
    UnitMorphs::Unit& unit = m.units.emplace_back();
    unit.channel = r.u8();
    if (!r.failed() && (unit.channel >= kAuChannelCount || (i > 0 && unit.channel <= m.units[i - 1].channel)))
      fail(error, MessageError::value_out_of_range);
    read_moves(r, unit.moves, error);
  }
  return finish(r, error);
}

MessageError read_message(std::span<const std::uint8_t> bytes, PreviewSurface& m) {
  ByteReader r(bytes);
  if (auto e = check_first_byte(r, bytes.size(), MessageType::preview_surface, kMaxDownstreamMessageBytes);
      e != MessageError::ok)
    return e;
  MessageError error = MessageError::ok;
  m.avatar = read_bounded(r, 3, kMaxAvatarIdValue, error);
  read_moves(r, m.moves, error);
  return finish(r, error);
}

}  // namespace fw::codec
