// Fuzzes the readers of every message a connection carries (codec/messages.hpp:
// hello, chat, command, set_rate and ping up; welcome, presence, command
// results, package chunks, pong, link statistics, closing, timed room frames,
// seats, attention, speaking and unit morphs down; and the codec's stream header and resync request
// that travel with them). The input is one message. classify() picks its
// reader from the first byte; the readers of every other type must refuse it
// at their type check. Whatever the bytes: no crash and no read outside the
// message, an error code the protocol knows, and a message that reads
// writes back to exactly the bytes read (the format has one spelling per
// message, so a reader that took another would read what no writer made;
// the writers' asserts check the values read are within their limits).
// Seeded with one message of each type (corpus/session_message_fuzz,
// written by fuzz_make_seeds).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"
#include "seed_check.hpp"

namespace {

using namespace fw::codec;
using Bytes = std::span<const std::uint8_t>;

bool same(Bytes a, const std::vector<std::uint8_t>& b) { return std::equal(a.begin(), a.end(), b.begin(), b.end()); }

// A seat coordinate is an i16 on the wire (PROTOCOL.md 4), which the reader
// takes whole, but the writers (C++ and the browser's) clamp to +-32767 mm:
// -32768 reads and is written back as -32767. Harmless (no seat is 33 m
// away), and the one value the round trip may change.
bool unwritable(const SeatInfo& s) { return s.x_mm == -32768.0f || s.y_mm == -32768.0f || s.z_mm == -32768.0f; }
template <class M>
bool holds_unwritable_seat(const M&) { return false; }
bool holds_unwritable_seat(const Presence& m) { return unwritable(m.avatar.seat); }
bool holds_unwritable_seat(const Welcome& m) {
  return std::any_of(m.avatars.begin(), m.avatars.end(), [](const AvatarInfo& a) { return unwritable(a.seat); });
}
bool holds_unwritable_seat(const Seats& m) {
  return std::any_of(m.seats.begin(), m.seats.end(), [](const Seats::Entry& e) { return unwritable(e.seat); });
}

/// Reads `bytes` as an M. `mine`: the first byte says M, so the reader must
/// get past its type check; else it must stop there.
template <class M>
void read_as(Bytes bytes, bool mine) {
  M message;
  const MessageError error = read_message(bytes, message);
  if (fw::codec::describe(error) == "unknown message error") std::abort();  // a code describe() does not know
  if (!mine) {
    // The size limit is checked before the type, so another type's reader
    // may call the message too large.
    if (error != MessageError::wrong_type && error != MessageError::too_large) std::abort();
    return;
  }
  if (error == MessageError::wrong_type || error == MessageError::unknown_type ||
      error == MessageError::not_session_message || error == MessageError::empty)
    std::abort();
  if (error != MessageError::ok) return fw::fuzz::seed_refused(fw::codec::describe(error));
  std::vector<std::uint8_t> written;
  write_message(message, written);
  if (!same(bytes, written) && !holds_unwritable_seat(message)) std::abort();
}

void read_session_message(Bytes bytes) {
  static_assert(kLastMessageType == MessageType::preview_surface, "a new message type: read it here and seed it");
  const MessageType t = session_type(bytes);
  read_as<Hello>(bytes, t == MessageType::hello);
  read_as<Welcome>(bytes, t == MessageType::welcome);
  read_as<Presence>(bytes, t == MessageType::presence);
  read_as<Chat>(bytes, t == MessageType::chat);
  read_as<Command>(bytes, t == MessageType::command);
  read_as<CommandResult>(bytes, t == MessageType::command_result);
  read_as<PackageChunk>(bytes, t == MessageType::package_chunk);
  read_as<SetRate>(bytes, t == MessageType::set_rate);
  read_as<Ping>(bytes, t == MessageType::ping);
  read_as<Pong>(bytes, t == MessageType::pong);
  read_as<LinkStats>(bytes, t == MessageType::link_stats);
  read_as<Closing>(bytes, t == MessageType::closing);
  read_as<TimedRoomFrame>(bytes, t == MessageType::timed_room_frame);
  read_as<Seats>(bytes, t == MessageType::seats);
  read_as<Attention>(bytes, t == MessageType::attention);
  read_as<Speaking>(bytes, t == MessageType::speaking);
  read_as<UnitMorphs>(bytes, t == MessageType::unit_morphs);
  read_as<PreviewSurface>(bytes, t == MessageType::preview_surface);
}

/// A reader of something else must refuse the message before its fields.
void refused_by_every_session_reader(Bytes bytes) {
  Hello hello;
  const MessageError error = read_message(bytes, hello);
  if (error != MessageError::empty && error != MessageError::not_session_message &&
      error != MessageError::unknown_type && error != MessageError::too_large)
    std::abort();
}

void read_stream_header_message(Bytes bytes) {
  StreamOptions options;
  const DecodeError error = read_stream_header(bytes, options);
  if (error > DecodeError::trailing_bytes) std::abort();
  if (error != DecodeError::ok) return fw::fuzz::seed_refused(fw::codec::describe(error));
  if (!same(bytes, write_stream_header(options))) std::abort();
}

void read_resync_request_message(Bytes bytes) {
  std::vector<std::uint32_t> ids;
  const DecodeError error = read_resync_request(bytes, ids);
  if (error > DecodeError::trailing_bytes) std::abort();
  if (error != DecodeError::ok) return fw::fuzz::seed_refused(fw::codec::describe(error));
  if (ids.size() > kMaxRoomAvatars) std::abort();
  std::vector<std::uint8_t> written;
  write_resync_request(ids, written);
  if (!same(bytes, written)) std::abort();
}

void read_room_frame_message(Bytes bytes) {
  std::vector<RoomEntry> entries;
  const DecodeError error = read_room_frame(bytes, entries);
  if (error > DecodeError::trailing_bytes) std::abort();
  if (error != DecodeError::ok) return fw::fuzz::seed_refused(fw::codec::describe(error));
  if (entries.empty() || entries.size() > kMaxRoomAvatars) std::abort();
  for (const RoomEntry& e : entries)
    if (e.avatar_id > kMaxAvatarId || e.frame.empty() || e.frame.size() > kMaxFrameBytes ||
        e.frame.data() < bytes.data() || e.frame.data() + e.frame.size() > bytes.data() + bytes.size())
      std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Bytes bytes(data, size);
  switch (classify(bytes)) {
    case MessageKind::session:
      read_session_message(bytes);
      break;
    case MessageKind::stream_header:
      refused_by_every_session_reader(bytes);
      read_stream_header_message(bytes);
      break;
    case MessageKind::resync_request:
      refused_by_every_session_reader(bytes);
      read_resync_request_message(bytes);
      break;
    case MessageKind::room_frame:
      refused_by_every_session_reader(bytes);
      read_room_frame_message(bytes);
      break;
    case MessageKind::invalid:
      refused_by_every_session_reader(bytes);
      fw::fuzz::seed_refused("no message starts with this first byte");
      break;
  }
  return 0;
}
