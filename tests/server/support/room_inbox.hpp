#pragma once
// What a room-protocol client received, filed by kind: welcome, presence,
// chat, command results, closing, link statistics, seats, attention, speaking, unit morphs, preview surfaces, room frames decoded by a
// codec::RoomDecoder, package chunks reassembled, and anything a correct
// server never sends. Shared by the socket client (room_test_client.hpp)
// and the in-memory peer (in_memory_server.hpp).
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"

namespace fw::test {

struct RoomInbox {
  std::optional<codec::Welcome> welcome;
  std::optional<codec::Closing> closing;
  std::optional<codec::LinkStats> link;  ///< the latest
  bool stream_header = false;
  std::vector<codec::Presence> presence;
  std::vector<codec::Chat> chat;
  std::vector<codec::CommandResult> results;
  std::vector<codec::Pong> pongs;
  std::vector<codec::Seats> seats;
  std::vector<codec::Attention> attention;
  std::vector<codec::Speaking> speaking;
  std::vector<codec::UnitMorphs> unit_morphs;
  std::vector<codec::PreviewSurface> preview_surfaces;
  /// For each speaking message: the tick of the last timed room frame
  /// filed before it (0: none), to check it came before its line's frame.
  std::vector<std::uint32_t> last_tick_before_speaking;
  std::uint64_t room_frames = 0;
  std::uint64_t bytes_received = 0;
  std::uint64_t room_frame_bytes = 0;  ///< of the codec room frames (timestamps excluded)
  std::uint64_t package_bytes = 0;     ///< of package chunk messages
  std::map<std::uint32_t, std::uint64_t> frames_per_avatar;
  std::vector<std::string> errors;  ///< anything a correct server never sends
  /// Timed room frames: when each arrived and its tick.
  std::vector<std::pair<std::chrono::steady_clock::time_point, std::uint32_t>> ticks;
  /// Timed room frames: the server's clock when each was simulated.
  std::vector<std::uint64_t> server_times_us;
  /// Arrival minus the server's tick time (same host, same monotonic clock).
  std::vector<std::int64_t> latency_us;
  struct Package {
    std::vector<std::uint8_t> bytes;
    std::size_t received = 0;
    bool complete() const { return !bytes.empty() && received == bytes.size(); }
  };
  std::map<std::pair<std::uint32_t, int>, Package> packages;  ///< (avatar, quality)
  std::vector<std::pair<std::uint32_t, int>> package_order;   ///< as completed
  codec::RoomDecoder decoder;

  static std::int64_t now_us() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }

  void file(const std::vector<std::uint8_t>& m) {
    bytes_received += m.size();
    switch (codec::classify(m)) {
      case codec::MessageKind::stream_header: stream_header = true; return;
      case codec::MessageKind::room_frame: return file_room_frame(m);
      case codec::MessageKind::session: break;
      default: errors.push_back("unexpected first byte " + std::to_string(m.empty() ? -1 : m[0])); return;
    }
    switch (codec::session_type(m)) {
      case codec::MessageType::welcome: return file_as(m, welcome, "welcome");
      case codec::MessageType::presence: return file_presence(m);
      case codec::MessageType::chat: return file_into(m, chat, "chat");
      case codec::MessageType::command_result: return file_into(m, results, "command result");
      case codec::MessageType::closing: return file_as(m, closing, "closing");
      case codec::MessageType::timed_room_frame: return file_timed_room_frame(m);
      case codec::MessageType::package_chunk: return file_package_chunk(m);
      case codec::MessageType::link_stats: return file_as(m, link, "link statistics");
      case codec::MessageType::pong: return file_into(m, pongs, "pong");
      case codec::MessageType::seats: return file_into(m, seats, "seats");
      case codec::MessageType::attention: return file_into(m, attention, "attention");
      case codec::MessageType::speaking:
        last_tick_before_speaking.push_back(ticks.empty() ? 0 : ticks.back().second);
        return file_into(m, speaking, "speaking");
      case codec::MessageType::unit_morphs: return file_into(m, unit_morphs, "unit morphs");
      case codec::MessageType::preview_surface: return file_into(m, preview_surfaces, "preview surface");
      default: errors.push_back("a message the server never sends"); return;
    }
  }

  void file_room_frame(const std::vector<std::uint8_t>& m) {
    ++room_frames;
    room_frame_bytes += m.size();
    const auto result = decoder.decode(m);
    if (result.error != codec::DecodeError::ok) {
      errors.push_back("room frame: " + std::string(codec::describe(result.error)));
      return;
    }
    for (const auto& [id, error] : result.avatars) {
      if (error != codec::DecodeError::ok) errors.push_back("avatar frame: " + std::string(codec::describe(error)));
      ++frames_per_avatar[id];
    }
  }

 private:
  bool check(codec::MessageError e, const char* what) {
    if (e != codec::MessageError::ok) errors.push_back(std::string(what) + ": " + std::string(codec::describe(e)));
    return e == codec::MessageError::ok;
  }
  template <class Message>
  void file_as(const std::vector<std::uint8_t>& m, std::optional<Message>& slot, const char* what) {
    Message message;
    if (check(codec::read_message(m, message), what)) slot = std::move(message);
  }
  template <class Message>
  void file_into(const std::vector<std::uint8_t>& m, std::vector<Message>& list, const char* what) {
    Message message;
    if (check(codec::read_message(m, message), what)) list.push_back(std::move(message));
  }
  void file_presence(const std::vector<std::uint8_t>& m) {
    codec::Presence p;
    if (!check(codec::read_message(m, p), "presence")) return;
    if (p.change == codec::Presence::Change::left) decoder.remove(p.avatar.id);
    presence.push_back(p);
  }
  void file_timed_room_frame(const std::vector<std::uint8_t>& m) {
    codec::TimedRoomFrame t;
    if (!check(codec::read_message(m, t), "timed room frame")) return;
    ticks.emplace_back(std::chrono::steady_clock::now(), t.tick);
    server_times_us.push_back(t.server_time_us);
    latency_us.push_back(now_us() - static_cast<std::int64_t>(t.server_time_us));
    if (!errors.empty()) return;
    file_room_frame(std::vector<std::uint8_t>(t.room_frame.begin(), t.room_frame.end()));
  }
  void file_package_chunk(const std::vector<std::uint8_t>& m) {
    codec::PackageChunk c;
    package_bytes += m.size();
    if (!check(codec::read_message(m, c), "package chunk")) return;
    auto& p = packages[{c.avatar, static_cast<int>(c.quality)}];
    if (p.complete() && c.offset == 0) p = Package{};  // another face for the avatar (its own was deleted)
    if (p.bytes.empty()) p.bytes.resize(c.total_bytes);
    if (p.bytes.size() != c.total_bytes || c.offset != p.received) {
      errors.push_back("package chunk out of order");
      return;
    }
    std::copy(c.data.begin(), c.data.end(), p.bytes.begin() + c.offset);
    p.received += c.data.size();
    if (p.complete()) package_order.emplace_back(c.avatar, static_cast<int>(c.quality));
  }
};

}  // namespace fw::test
