#include "bridge_message.hpp"

#include "fw/codec/byte_reader.hpp"
#include "fw/codec/byte_writer.hpp"

namespace fw::server::bridge {
namespace {

using codec::ByteReader;
using codec::ByteWriter;

void put_text(ByteWriter& w, const std::string& text) {
  w.varint(static_cast<std::uint32_t>(text.size()));
  w.bytes({reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}
std::string get_text(ByteReader& r) {
  const std::uint32_t size = r.varint();
  const auto bytes = r.bytes(r.failed() ? 0 : size);  // past the end: the reader fails
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}
void put_bytes(ByteWriter& w, const Bytes& bytes) {
  w.varint(static_cast<std::uint32_t>(bytes.size()));
  w.bytes(bytes);
}
Bytes get_bytes(ByteReader& r) {
  const std::uint32_t size = r.varint();
  const auto bytes = r.bytes(r.failed() ? 0 : size);
  return {bytes.begin(), bytes.end()};
}

void put_info(ByteWriter& w, const codec::AvatarInfo& info) {
  w.u32_le(info.id);
  put_text(w, info.name);
  put_text(w, info.asset);
  w.u32_le(info.preview_bytes);
  w.u32_le(info.full_bytes);
  w.u8(info.person ? 1 : 0);
  w.f32_le(info.seat.x_mm);
  w.f32_le(info.seat.y_mm);
  w.f32_le(info.seat.z_mm);
  w.f32_le(info.seat.facing_yaw_rad);
}
codec::AvatarInfo get_info(ByteReader& r) {
  codec::AvatarInfo info;
  info.id = r.u32_le();
  info.name = get_text(r);
  info.asset = get_text(r);
  info.preview_bytes = r.u32_le();
  info.full_bytes = r.u32_le();
  info.person = r.u8() != 0;
  info.seat.x_mm = r.f32_le();
  info.seat.y_mm = r.f32_le();
  info.seat.z_mm = r.f32_le();
  info.seat.facing_yaw_rad = r.f32_le();
  return info;
}

void put_member(ByteWriter& w, const MemberRecord& m) {
  put_info(w, m.info);
  put_text(w, m.node);
  put_text(w, m.address);
  put_text(w, m.resume_hash);
  w.u32_le(static_cast<std::uint32_t>(m.order >> 32));
  w.u32_le(static_cast<std::uint32_t>(m.order));
  put_text(w, m.language);
  put_bytes(w, m.unit_morphs);
}
MemberRecord get_member(ByteReader& r) {
  MemberRecord m;
  m.info = get_info(r);
  m.node = get_text(r);
  m.address = get_text(r);
  m.resume_hash = get_text(r);
  const std::uint64_t high = r.u32_le();
  m.order = high << 32 | r.u32_le();
  m.language = get_text(r);
  m.unit_morphs = get_bytes(r);
  return m;
}

// Every float of the face, in declaration order: exact, so that each node's
// encoders see what the owner simulated.
template <class Visit>
void each_float(codec::FaceParams& f, Visit visit) {
  for (float& v : f.au) visit(v);
  visit(f.head_yaw_rad);
  visit(f.head_pitch_rad);
  visit(f.head_roll_rad);
  for (float& v : f.head_translation_mm) visit(v);
  visit(f.eye_left.yaw_rad);
  visit(f.eye_left.pitch_rad);
  visit(f.eye_right.yaw_rad);
  visit(f.eye_right.pitch_rad);
  visit(f.lid_left);
  visit(f.lid_right);
  for (float& v : f.blush) visit(v);
  visit(f.pallor);
  for (float& v : f.corrective) visit(v);
}

Bytes start(std::uint8_t kind) { return {kVersion, kind}; }

}  // namespace

Down down_roster() {
  Down m;
  m.kind = DownKind::roster;
  return m;
}
Down down_joined(std::string join_ref, MemberRecord member, bool returning) {
  Down m;
  m.kind = DownKind::joined;
  m.join_ref = std::move(join_ref);
  m.member = std::move(member);
  m.returning = returning;
  return m;
}
Down down_refused(std::string join_ref, codec::CloseCode code, std::string reason) {
  Down m;
  m.kind = DownKind::refused;
  m.join_ref = std::move(join_ref);
  m.code = code;
  m.reason = std::move(reason);
  return m;
}
Down down_left(std::uint32_t avatar) {
  Down m;
  m.kind = DownKind::left;
  m.avatar = avatar;
  return m;
}
Down down_message(DownKind kind, std::uint32_t avatar, Bytes message) {
  Down m;
  m.kind = kind;
  m.avatar = avatar;
  m.message = std::move(message);
  return m;
}
Down down_attention(Bytes attention) {
  Down m;
  m.kind = DownKind::attention;
  m.attention = std::move(attention);
  return m;
}
Down down_tick(std::uint32_t tick) {
  Down m;
  m.kind = DownKind::tick;
  m.tick = tick;
  return m;
}
Up up_sync(std::string node) {
  Up m;
  m.kind = UpKind::sync;
  m.node = std::move(node);
  return m;
}
Up up_leave(std::string node, std::uint32_t avatar) {
  Up m = up_sync(std::move(node));
  m.kind = UpKind::leave;
  m.avatar = avatar;
  return m;
}
Up up_chat(std::string node, std::uint32_t avatar, std::string text) {
  Up m = up_leave(std::move(node), avatar);
  m.kind = UpKind::chat;
  m.text = std::move(text);
  return m;
}
Up up_command(std::string node, std::uint32_t avatar, Bytes command) {
  Up m = up_leave(std::move(node), avatar);
  m.kind = UpKind::command;
  m.command = std::move(command);
  return m;
}

Bytes encode(const MemberRecord& record) {
  Bytes out{kVersion};
  ByteWriter w(out);
  put_member(w, record);
  return out;
}

std::optional<MemberRecord> decode_member(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || data[0] != kVersion) return std::nullopt;
  ByteReader r({data + 1, size - 1});
  MemberRecord m = get_member(r);
  if (r.failed() || r.remaining() != 0) return std::nullopt;
  return m;
}

Bytes encode(const RoomState& state) {
  Bytes out{kVersion};
  ByteWriter w(out);
  w.varint(static_cast<std::uint32_t>(state.moods.size()));
  for (const auto& mood : state.moods) {
    w.u32_le(mood.avatar);
    w.varint(static_cast<std::uint32_t>(mood.values.size()));
    for (const float v : mood.values) w.f32_le(v);
  }
  return out;
}

std::optional<RoomState> decode_state(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || data[0] != kVersion) return std::nullopt;
  ByteReader r({data + 1, size - 1});
  RoomState state;
  const std::uint32_t count = r.varint();
  if (count > 4096) return std::nullopt;
  for (std::uint32_t i = 0; i < count && !r.failed(); ++i) {
    RoomState::Mood mood;
    mood.avatar = r.u32_le();
    const std::uint32_t values = r.varint();
    if (values > 64) return std::nullopt;
    for (std::uint32_t v = 0; v < values; ++v) mood.values.push_back(r.f32_le());
    state.moods.push_back(std::move(mood));
  }
  if (r.failed() || r.remaining() != 0) return std::nullopt;
  return state;
}

Bytes encode(const Down& m) {
  Bytes out = start(static_cast<std::uint8_t>(m.kind));
  ByteWriter w(out);
  put_text(w, m.owner);
  switch (m.kind) {
    case DownKind::roster:
      w.varint(static_cast<std::uint32_t>(m.members.size()));
      for (const auto& member : m.members) put_member(w, member);
      put_bytes(w, m.attention);
      break;
    case DownKind::joined:
      put_text(w, m.join_ref);
      put_member(w, m.member);
      w.u8(m.returning ? 1 : 0);
      break;
    case DownKind::refused:
      put_text(w, m.join_ref);
      w.u16_le(static_cast<std::uint16_t>(m.code));
      put_text(w, m.reason);
      break;
    case DownKind::left: w.u32_le(m.avatar); break;
    case DownKind::attention: put_bytes(w, m.attention); break;
    case DownKind::seats:
    case DownKind::chat:
    case DownKind::result:
    case DownKind::speaking:
    case DownKind::unit_morphs:
      w.u32_le(m.avatar);
      put_bytes(w, m.message);
      break;
    case DownKind::tick:
      w.u32_le(m.tick);
      w.varint(static_cast<std::uint32_t>(m.faces.size()));
      for (const FaceEntry& entry : m.faces) {
        w.u32_le(entry.id);
        codec::FaceParams face = entry.face;
        each_float(face, [&](float& v) { w.f32_le(v); });
      }
      break;
  }
  return out;
}

std::optional<Down> decode_down(const std::uint8_t* data, std::size_t size) {
  if (size < 2 || data[0] != kVersion || data[1] < 1 || data[1] > static_cast<std::uint8_t>(DownKind::unit_morphs))
    return std::nullopt;
  Down m;
  m.kind = static_cast<DownKind>(data[1]);
  ByteReader r({data + 2, size - 2});
  m.owner = get_text(r);
  switch (m.kind) {
    case DownKind::roster: {
      const std::uint32_t count = r.varint();
      if (count > 4096) return std::nullopt;
      for (std::uint32_t i = 0; i < count && !r.failed(); ++i) m.members.push_back(get_member(r));
      m.attention = get_bytes(r);
      break;
    }
    case DownKind::joined:
      m.join_ref = get_text(r);
      m.member = get_member(r);
      m.returning = r.u8() != 0;
      break;
    case DownKind::refused:
      m.join_ref = get_text(r);
      m.code = static_cast<codec::CloseCode>(r.u16_le());
      m.reason = get_text(r);
      break;
    case DownKind::left: m.avatar = r.u32_le(); break;
    case DownKind::attention: m.attention = get_bytes(r); break;
    case DownKind::seats:
    case DownKind::chat:
    case DownKind::result:
    case DownKind::speaking:
    case DownKind::unit_morphs:
      m.avatar = r.u32_le();
      m.message = get_bytes(r);
      break;
    case DownKind::tick: {
      m.tick = r.u32_le();
      const std::uint32_t count = r.varint();
      if (count > 4096) return std::nullopt;
      m.faces.resize(count);
      for (FaceEntry& entry : m.faces) {
        entry.id = r.u32_le();
        each_float(entry.face, [&](float& v) { v = r.f32_le(); });
      }
      break;
    }
  }
  if (r.failed() || r.remaining() != 0) return std::nullopt;
  return m;
}

Bytes encode(const Up& m) {
  Bytes out = start(static_cast<std::uint8_t>(m.kind));
  ByteWriter w(out);
  put_text(w, m.node);
  switch (m.kind) {
    case UpKind::sync: break;
    case UpKind::join:
      put_text(w, m.join_ref);
      put_text(w, m.name);
      put_text(w, m.asset);
      put_text(w, m.address);
      put_text(w, m.resume_hash);
      put_text(w, m.returning);
      put_text(w, m.language);
      break;
    case UpKind::leave: w.u32_le(m.avatar); break;
    case UpKind::chat:
      w.u32_le(m.avatar);
      put_text(w, m.text);
      break;
    case UpKind::command:
      w.u32_le(m.avatar);
      put_bytes(w, m.command);
      break;
  }
  return out;
}

std::optional<Up> decode_up(const std::uint8_t* data, std::size_t size) {
  if (size < 2 || data[0] != kVersion || data[1] < 1 || data[1] > static_cast<std::uint8_t>(UpKind::command))
    return std::nullopt;
  Up m;
  m.kind = static_cast<UpKind>(data[1]);
  ByteReader r({data + 2, size - 2});
  m.node = get_text(r);
  switch (m.kind) {
    case UpKind::sync: break;
    case UpKind::join:
      m.join_ref = get_text(r);
      m.name = get_text(r);
      m.asset = get_text(r);
      m.address = get_text(r);
      m.resume_hash = get_text(r);
      m.returning = get_text(r);
      m.language = get_text(r);
      break;
    case UpKind::leave: m.avatar = r.u32_le(); break;
    case UpKind::chat:
      m.avatar = r.u32_le();
      m.text = get_text(r);
      break;
    case UpKind::command:
      m.avatar = r.u32_le();
      m.command = get_bytes(r);
      break;
  }
  if (r.failed() || r.remaining() != 0) return std::nullopt;
  return m;
}

}  // namespace fw::server::bridge
