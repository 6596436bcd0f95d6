#pragma once
// A room connection for tests without sockets: it keeps every message, and
// its "socket" drains a set number of bytes a tick, so that a thin one
// backs up and the stream holds ticks. Also a face that keeps moving.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "room_connection.hpp"

namespace fw::test {

/// The rooms' tick rate in these tests, and a tick in microseconds.
inline constexpr int kRoomTickHz = 30;
inline constexpr std::uint64_t kRoomTickUs = 1'000'000 / kRoomTickHz;

class DrainingConnection : public server::RoomConnection {
 public:
  explicit DrainingConnection(std::size_t drain_per_tick) : drain_per_tick_(drain_per_tick) {}
  void deliver(server::SharedBytes message) override {
    queued_ += message->size();
    messages_.push_back(std::move(message));
  }
  std::size_t queued_bytes() const override { return queued_; }
  std::uint64_t bytes_written() const override { return written_; }
  std::size_t framing_bytes(std::size_t) const override { return 2; }
  void close(codec::CloseCode, std::string) override {}
  void joined(std::uint32_t, server::SharedBytes) override {}

  void drain_a_tick() {
    const std::size_t n = std::min(queued_, drain_per_tick_);
    queued_ -= n;
    written_ += n;
  }
  const std::vector<server::SharedBytes>& messages() const { return messages_; }

 private:
  std::size_t drain_per_tick_;
  std::size_t queued_ = 0;
  std::uint64_t written_ = 0;
  std::vector<server::SharedBytes> messages_;
};

/// A face that keeps moving, different for every avatar.
inline codec::FaceParams moving_face_of(std::uint32_t avatar, std::uint32_t tick) {
  codec::FaceParams face;
  const float t = static_cast<float>(tick) + 17.0f * static_cast<float>(avatar);
  face.set_au(12, 0.4f + 0.3f * std::sin(t * 0.11f));
  face.set_au(26, 0.3f + 0.3f * std::sin(t * 0.37f));
  face.set_au(4, 0.2f + 0.2f * std::sin(t * 0.05f));
  face.head_yaw_rad = 0.3f * std::sin(t * 0.04f);
  face.head_pitch_rad = 0.1f * std::sin(t * 0.06f);
  face.eye_left.yaw_rad = face.eye_right.yaw_rad = (static_cast<int>(t) / 40) % 2 == 0 ? 0.2f : -0.25f;
  face.corrective[0] = 0.5f * std::sin(t * 0.03f);
  return face;
}

}  // namespace fw::test
