#pragma once
// The room server's side of the protocol, for the client's tests: messages
// made with the codec's own writers (fw/codec/messages.hpp, codec.hpp), and
// avatars' faces encoded as the server encodes them, so that what the
// client reads is what a server would send.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"

namespace fw::client::test {

using Bytes = std::vector<std::uint8_t>;

template <class Message>
Bytes bytes_of(const Message& message) {
  Bytes out;
  codec::write_message(message, out);
  return out;
}

/// Reads an upstream message as `Message`; a test failure if it is not one.
template <class Message>
Message read_as(const Bytes& bytes) {
  Message message;
  EXPECT_EQ(codec::read_message(bytes, message), codec::MessageError::ok);
  return message;
}

inline codec::AvatarInfo avatar_info(std::uint32_t id, const std::string& name, const std::string& asset = "") {
  codec::AvatarInfo info;
  info.id = id;
  info.name = name;
  info.asset = asset;
  return info;
}

inline Bytes welcome(std::uint32_t you, std::vector<codec::AvatarInfo> avatars, const std::string& room = "lobby") {
  codec::Welcome message;
  message.you = you;
  message.room = room;
  message.avatars = std::move(avatars);
  return bytes_of(message);
}

inline Bytes stream_header() { return codec::write_stream_header(codec::StreamOptions{}); }

inline Bytes presence(codec::Presence::Change change, const codec::AvatarInfo& avatar) {
  return bytes_of(codec::Presence{change, avatar});
}

inline Bytes chat_from(std::uint32_t from, const std::string& text) { return bytes_of(codec::Chat{from, text}); }

inline Bytes closing(codec::CloseCode code, const std::string& reason) { return bytes_of(codec::Closing{code, reason}); }

/// A package in chunks of at most `chunk_bytes`, in order.
inline std::vector<Bytes> package_chunks(std::uint32_t avatar, codec::PackageChunk::Quality quality,
                                         const Bytes& package, std::size_t chunk_bytes) {
  std::vector<Bytes> chunks;
  for (std::size_t offset = 0; offset < package.size(); offset += chunk_bytes) {
    const std::size_t end = std::min(package.size(), offset + chunk_bytes);
    codec::PackageChunk chunk{avatar, quality, static_cast<std::uint32_t>(package.size()),
                              static_cast<std::uint32_t>(offset), Bytes(package.begin() + offset, package.begin() + end)};
    chunks.push_back(bytes_of(chunk));
  }
  return chunks;
}

/// A face with an expression: `amount` 0 .. 1 of a smile and a turn of the head.
inline codec::FaceParams face(float amount) {
  codec::FaceParams params;
  params.set_au(12, amount);
  params.set_au(6, amount * 0.5f);
  params.head_yaw_rad = 0.3f * amount;
  return params;
}

/// One avatar's stream, encoded as the server would: a key frame first,
/// predicted frames after it.
class FaceStream {
 public:
  FaceStream() : encoder_(options()) {}

  /// The next frame that carries `params` (the encoder skips ticks that
  /// would show no difference; this offers the face until one comes out).
  Bytes frame(const codec::FaceParams& params) {
    Bytes frame;
    for (int tick = 0; tick < 90 && frame.empty(); ++tick) encoder_.encode(params, frame);
    EXPECT_FALSE(frame.empty()) << "the encoder sent nothing for 90 ticks";
    return frame;
  }
  /// What a decoder of this stream shows now, exactly.
  codec::QuantisedParams reconstruction() const { return encoder_.reconstruction(); }

 private:
  static codec::EncoderOptions options() {
    codec::EncoderOptions options;
    options.target_bps = 1'000'000;  // every change goes out at once
    return options;
  }
  codec::Encoder encoder_;
};

/// A room frame holding each avatar's frame.
inline Bytes room_frame(const std::vector<std::pair<std::uint32_t, Bytes>>& frames) {
  std::vector<codec::RoomEntry> entries;
  for (const auto& [avatar, frame] : frames) entries.push_back({avatar, frame});
  Bytes out;
  codec::write_room_frame(entries, out);
  return out;
}

/// A room frame stamped with its tick and the server's time.
inline Bytes timed(const Bytes& room_frame, std::uint32_t tick, std::uint64_t server_time_us) {
  return bytes_of(codec::TimedRoomFrame{tick, server_time_us, room_frame});
}

}  // namespace fw::client::test
