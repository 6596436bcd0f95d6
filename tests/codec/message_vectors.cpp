// Writes what the C++ session-message code does with a set of messages, for
// the browser's port (web/protocol) to be checked against: each message's
// fields and bytes, and, for every cut, altered and lengthened copy of
// them, what the C++ reader says (and, when it reads, the bytes it writes
// back). Usage: codec_message_vectors OUT.json. The ctest codec_js_messages
// runs it into the build tree and then node's test runner on the port, so
// the vectors are always the code's own.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "fw/codec/messages.hpp"
#include "sample_messages.hpp"

namespace fw::codec {
namespace {

using nlohmann::json;

std::string hex(std::span<const std::uint8_t> bytes) {
  std::string s;
  char b[3];
  for (const std::uint8_t x : bytes) {
    std::snprintf(b, sizeof b, "%02x", x);
    s += b;
  }
  return s;
}

json seat_json(const SeatInfo& s) {
  return {{"xMm", s.x_mm}, {"yMm", s.y_mm}, {"zMm", s.z_mm}, {"facingYawRad", s.facing_yaw_rad}};
}
json info_json(const AvatarInfo& a) {
  return {{"id", a.id},   {"person", a.person}, {"name", a.name}, {"asset", a.asset}, {"previewBytes", a.preview_bytes},
          {"fullBytes", a.full_bytes}, {"seat", seat_json(a.seat)}};
}

// The fields of each message as the port names them (camelCase).
json fields(const Hello& m) {
  return {{"protocolVersion", m.protocol_version}, {"timestamps", m.timestamps}, {"noPackages", m.no_packages},
          {"ownPackage", m.own_package}, {"preview", m.preview}, {"maxBps", m.max_bps}, {"room", m.room}, {"name", m.name},
          {"avatar", m.avatar}, {"token", m.token}, {"avatarKey", m.avatar_key}, {"resume", m.resume},
          {"language", m.language}};
}
json fields(const Welcome& m) {
  json avatars = json::array();
  for (const auto& a : m.avatars) avatars.push_back(info_json(a));
  return {{"protocolVersion", m.protocol_version}, {"you", m.you}, {"room", m.room}, {"tickHz", m.tick_hz},
          {"maxBps", m.max_bps}, {"avatars", avatars}, {"resume", m.resume}};
}
json fields(const Presence& m) { return {{"change", static_cast<int>(m.change)}, {"avatar", info_json(m.avatar)}}; }
json fields(const Chat& m) { return {{"from", m.from}, {"text", m.text}}; }
json fields(const Command& m) {
  return {{"requestId", m.request_id}, {"kind", static_cast<int>(m.kind)}, {"emotion", m.emotion},
          {"intensity", m.intensity}, {"target", m.target}, {"durationMs", m.duration_ms}, {"sentence", m.sentence},
          {"override", {{"part", static_cast<int>(m.override_face.part)}, {"index", m.override_face.index},
                        {"side", m.override_face.side}, {"value", m.override_face.value}}}};
}
json fields(const CommandResult& m) { return {{"requestId", m.request_id}, {"error", m.error}}; }
json fields(const PackageChunk& m) {
  return {{"avatar", m.avatar}, {"quality", static_cast<int>(m.quality)}, {"totalBytes", m.total_bytes},
          {"offset", m.offset}, {"data", hex(m.data)}};
}
json fields(const SetRate& m) { return {{"maxBps", m.max_bps}}; }
json fields(const Ping& m) { return {{"nonce", m.nonce}, {"clientTimeUs", m.client_time_us}}; }
json fields(const Pong& m) {
  return {{"nonce", m.nonce}, {"clientTimeUs", m.client_time_us}, {"serverTimeUs", m.server_time_us}};
}
json fields(const LinkStats& m) {
  return {{"targetBps", m.target_bps}, {"drainBps", m.drain_bps}, {"queuedBytes", m.queued_bytes},
          {"skippedTicks", m.skipped_ticks}};
}
json fields(const Closing& m) { return {{"code", static_cast<int>(m.code)}, {"reason", m.reason}}; }
json fields(const TimedRoomFrame& m) {
  return {{"tick", m.tick}, {"serverTimeUs", m.server_time_us}, {"roomFrame", hex(m.room_frame)}};
}
json fields(const Seats& m) {
  json seats = json::array();
  for (const auto& e : m.seats) seats.push_back({{"avatar", e.avatar}, {"seat", seat_json(e.seat)}});
  return {{"seats", seats}};
}
json fields(const Speaking& m) {
  return {{"avatar", m.avatar}, {"tick", m.tick}, {"durationMs", m.duration_ms}, {"language", m.language},
          {"text", m.text}};
}
json fields(const UnitMorphs& m) {
  json units = json::array();
  for (const auto& unit : m.units) {
    json moves = json::array();
    for (const auto& move : unit.moves) moves.push_back({{"vertex", move.vertex}, {"delta", move.delta}});
    units.push_back({{"channel", unit.channel}, {"moves", moves}});
  }
  return {{"avatar", m.avatar}, {"version", m.version}, {"units", units}};
}
json fields(const PreviewSurface& m) {
  json moves = json::array();
  for (const auto& move : m.moves) moves.push_back({{"vertex", move.vertex}, {"delta", move.delta}});
  return {{"avatar", m.avatar}, {"moves", moves}};
}
json fields(const Attention& m) {
  json entries = json::array();
  for (const auto& e : m.entries)
    entries.push_back({{"avatar", e.avatar}, {"target", static_cast<int>(e.target)}, {"targetAvatar", e.target_avatar}});
  return {{"entries", entries}};
}

template <class M>
std::vector<std::uint8_t> bytes_of(const M& m) {
  std::vector<std::uint8_t> out;
  write_message(m, out);
  return out;
}

/// What the reader of M says of `bytes`: its error, and when it reads, the
/// fields and the bytes written back.
template <class M>
json verdict(std::span<const std::uint8_t> bytes) {
  M m;
  const MessageError error = read_message(bytes, m);
  json v = {{"hex", hex(bytes)}, {"error", static_cast<int>(error)}};
  if (error == MessageError::ok) {
    v["fields"] = fields(m);
    v["rewritten"] = hex(bytes_of(m));
  }
  return v;
}

/// Every cut, altered and lengthened copy of `bytes`, read as M.
template <class M>
void damaged(const std::vector<std::uint8_t>& bytes, json& out) {
  const int type = bytes[0] & 0x7F;
  const auto add = [&](const std::vector<std::uint8_t>& b) {
    json v = verdict<M>(b);
    v["type"] = type;
    out.push_back(std::move(v));
  };
  for (std::size_t n = 0; n < bytes.size(); ++n) add({bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n)});
  for (std::size_t i = 0; i < bytes.size(); ++i)
    for (const std::uint8_t value : {0x00, 0x01, 0x7F, 0x80, 0xC3, 0xFF}) {
      auto b = bytes;
      if (b[i] == value) continue;
      b[i] = value;
      add(b);
    }
  auto longer = bytes;
  longer.push_back(0x00);
  add(longer);
}

struct Vectors {
  json messages = json::array();
  json damaged_messages = json::array();

  /// The fields are those read back: what the wire carries (seats in whole
  /// millimetres, intensity in hundredths), not what was given.
  template <class M>
  void add(const M& m) {
    const auto bytes = bytes_of(m);
    M back;
    if (read_message(bytes, back) != MessageError::ok) throw std::logic_error("a written message does not read");
    messages.push_back({{"type", bytes[0] & 0x7F}, {"hex", hex(bytes)}, {"fields", fields(back)}});
    damaged<M>(bytes, damaged_messages);
  }
};

json make_vectors() {
  Vectors v;
  v.add(fw::test::sample_hello());
  v.add(fw::test::sample_hello_v3());  // still read: a version-3 client, no language
  Hello plain;  // this version, with the server's default language
  plain.room = "r";
  plain.name = "A";
  plain.no_packages = true;
  v.add(plain);
  Welcome welcome;
  welcome.you = 300;
  welcome.room = "r-1.x";
  welcome.tick_hz = 30;
  welcome.max_bps = 56000;
  welcome.resume = "r-e_sume0123456789abcd";
  welcome.avatars = {{1, "Ada", "", 0, 0, false, {-364.0f, 0.0f, 210.0f, 1.0471976f}},
                     {300, "Bo 🙂", "ffeeddccbbaa99887766554433221100", 1100, 19652, true, {0, 0, -40.0f, -3.1415926f}}};
  v.add(welcome);
  welcome.protocol_version = 3;  // the answer to a version-3 hello: the same layout
  v.add(welcome);
  v.add(Presence{Presence::Change::joined, welcome.avatars[1]});
  v.add(Presence{Presence::Change::left, {300, "", "", 0, 0, true, {}}});
  v.add(Chat{300, "hello, room — ça va?"});
  v.add(Command{.request_id = 70000, .kind = Command::Kind::express, .emotion = "joy", .intensity = 0.7f,
                 .target = 0, .duration_ms = 2500, .sentence = ""});
  v.add(Command{.request_id = 2, .kind = Command::Kind::look_at, .emotion = "", .intensity = 1, .target = 2097151,
                .duration_ms = 600000, .sentence = ""});
  v.add(Command{.request_id = 3, .kind = Command::Kind::snub, .emotion = "", .intensity = 1, .target = 5,
                .duration_ms = 0, .sentence = ""});
  v.add(Command{.request_id = 4, .kind = Command::Kind::facs, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "AU12 0.8\n\tAU6 0.5"});
  v.add(Command{.request_id = 5, .kind = Command::Kind::override_face, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "", .override_face = {OverridePart::action_unit, 12, 1, 7500}});
  v.add(Command{.request_id = 6, .kind = Command::Kind::override_face, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "", .override_face = {OverridePart::head_yaw, 0, 0, -12000}});
  v.add(Command{.request_id = 7, .kind = Command::Kind::override_face, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "", .override_face = {OverridePart::muscle, 22, 0, 10000}});
  v.add(Command{.request_id = 8, .kind = Command::Kind::override_face, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "", .override_face = {OverridePart::skin_age, 0, 0, 5000}});
  v.add(Command{.request_id = 7, .kind = Command::Kind::check, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "ClearAllFrame\nBeginKeyFrame 12 1.0"});
  v.add(Command{.request_id = 8, .kind = Command::Kind::play_look, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "blush slowly"});
  v.add(CommandResult{4, "no such action unit"});
  v.add(PackageChunk{7, PackageChunk::Quality::full, 20000, 16000, {1, 2, 3, 250, 0}});
  v.add(SetRate{2400});
  v.add(Ping{0xDEADBEEF, 1234567890123ull});
  v.add(Pong{1, 2, 4503599627370495ull});
  v.add(LinkStats{9600, 9100, 312, 4000000000u});
  v.add(Closing{CloseCode::room_full, "room 'x' is full (16 avatars); try another room"});
  const std::vector<std::uint8_t> frame = {0x23, 0x01, 0x02};
  v.add(TimedRoomFrame{77, 99999999, frame});
  Seats seats;
  seats.seats = {{1, {-420.0f, 0.0f, 113.0f, 0.8727f}}, {2, {420.0f, 12.0f, 113.0f, -0.8727f}}};
  v.add(seats);
  Attention attention;
  attention.entries = {{1, AttentionTarget::avatar, 2}, {2, AttentionTarget::room, 0}, {3, AttentionTarget::nobody, 0}};
  v.add(attention);
  v.add(fw::test::sample_speaking());
  v.add(Speaking{.avatar = 2097151, .tick = 4294967295u, .duration_ms = kMaxSpeakingMs, .language = "zh-yue-1",
                 .text = "Ja."});
  v.add(Speaking{.avatar = 0, .tick = 0, .duration_ms = 0, .language = "x", .text = "."});
  v.add(fw::test::sample_unit_morphs());
  v.add(UnitMorphs{.avatar = 2097151, .version = 4294967295u, .units = {}});
  v.add(fw::test::sample_preview_surface());
  v.add(PreviewSurface{.avatar = 2097151, .moves = {}});
  return {{"protocolVersion", kProtocolVersion}, {"messages", v.messages}, {"damaged", v.damaged_messages}};
}

}  // namespace
}  // namespace fw::codec

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: codec_message_vectors OUT.json\n";
    return 2;
  }
  std::ofstream out(argv[1]);
  out << fw::codec::make_vectors().dump() << "\n";
  if (!out) {
    std::cerr << "cannot write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
