// Shared encoders without sockets: a room of viewers (SubscriberStreams
// over recording connections, ticked as a room ticks them, faces offered
// through the room's FaceSources) whose every message each viewer's own
// decoders read. Viewers on alike links share one encoder per face and
// still decode every frame, through joins in either order, a link that
// backs up, a budget far apart and a resync request.
#include "shared_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "draining_connection.hpp"
#include "face_sources.hpp"
#include "metrics.hpp"
#include "subscriber_stream.hpp"

namespace fw::server {
namespace {

using test::DrainingConnection;
using test::kRoomTickHz;
using test::kRoomTickUs;
using test::moving_face_of;

constexpr std::size_t kAmpleDrain = 1'000'000;

/// One viewer: its stream, and what its client decoded of what was sent.
struct RoomViewer {
  RoomViewer(std::uint32_t budget, std::size_t drain_per_tick, Metrics& metrics)
      : budget_bps(budget), connection(std::make_shared<DrainingConnection>(drain_per_tick)),
        stream(settings(budget), connection, metrics) {}
  static StreamSettings settings(std::uint32_t budget_bps) {
    StreamSettings s;
    s.tick_hz = kRoomTickHz;
    s.budget_bps = budget_bps;
    s.packages = false;
    return s;
  }

  /// Decodes what arrived since the last call, as a client would: every
  /// frame of every avatar must decode. Records each avatar's last frame type.
  void read() {
    const auto& messages = connection->messages();
    for (; read_ < messages.size(); ++read_) {
      const std::vector<std::uint8_t>& message = *messages[read_];
      if (codec::classify(message) != codec::MessageKind::room_frame) continue;
      std::vector<codec::RoomEntry> entries;
      ASSERT_EQ(codec::read_room_frame(message, entries), codec::DecodeError::ok);
      for (const codec::RoomEntry& entry : entries) {
        const codec::DecodeError error = decoders[entry.avatar_id].decode(entry.frame);
        ASSERT_EQ(error, codec::DecodeError::ok) << "avatar " << entry.avatar_id << ", frame " << frames;
        last_type[entry.avatar_id] = static_cast<codec::FrameType>(entry.frame[0] & 0x0F);
        ++frames;
      }
    }
  }

  /// Bytes of every message sent so far.
  std::uint64_t bytes() const {
    std::uint64_t sum = 0;
    for (const SharedBytes& message : connection->messages()) sum += message->size();
    return sum;
  }

  std::uint32_t budget_bps;
  std::shared_ptr<DrainingConnection> connection;
  SubscriberStream stream;
  std::map<std::uint32_t, codec::Decoder> decoders;
  std::map<std::uint32_t, codec::FrameType> last_type;
  std::size_t read_ = 0;
  std::uint64_t frames = 0;
};

/// A room's viewers of a few faces, ticked in the order given.
struct ViewedRoom {
  RoomViewer& add_viewer(std::uint32_t budget_bps, std::size_t drain_per_tick = kAmpleDrain) {
    viewers.push_back(std::make_unique<RoomViewer>(budget_bps, drain_per_tick, metrics));
    for (const std::uint32_t id : avatars) viewers.back()->stream.add_avatar(id, nullptr, nullptr);
    order.insert(order.begin(), viewers.size() - 1);  // the newest is ticked first
    return *viewers.back();
  }
  void tick() {
    ++tick_index;
    now_us += kRoomTickUs;
    std::vector<codec::FaceParams> params;
    for (const std::uint32_t id : avatars) params.push_back(moving_face_of(id, tick_index));
    std::vector<AvatarFace> faces;
    for (std::size_t i = 0; i < avatars.size(); ++i) faces.push_back({avatars[i], &params[i]});
    sources.offer(faces);
    for (const std::size_t v : order) viewers[v]->stream.tick(tick_index, now_us, faces);
    for (const auto& viewer : viewers) {
      if (!viewer) continue;
      viewer->connection->drain_a_tick();
      viewer->read();
    }
  }
  void run(int ticks) {
    for (int i = 0; i < ticks && !::testing::Test::HasFatalFailure(); ++i) tick();
  }
  /// Reverses the order viewers are ticked in (a room ticks its members by id).
  void reverse_order() { std::reverse(order.begin(), order.end()); }
  /// Viewer `v` is gone (its connection closed): its stream goes with it.
  void drop_viewer(std::size_t v) {
    viewers[v].reset();
    std::erase(order, v);
  }

  Metrics metrics;
  std::vector<std::uint32_t> avatars = {1, 2, 3};
  std::vector<std::unique_ptr<RoomViewer>> viewers;
  std::vector<std::size_t> order;
  FaceSources sources;
  std::uint32_t tick_index = 0;
  std::uint64_t now_us = 1;
};

/// How far viewer `v`'s decoded smile is from the face's at the room's tick.
float smile_error(ViewedRoom& room, std::size_t v, std::uint32_t avatar) {
  return std::abs(room.viewers[v]->decoders[avatar].face().au_intensity(12) - moving_face_of(avatar, room.tick_index).au_intensity(12));
}

TEST(SharedEncoders, ViewersOnAlikeLinksShareOneEncoderPerFaceAndDecodeEveryFrame) {
  ViewedRoom room;
  room.add_viewer(48000);
  room.run(20);
  room.add_viewer(48000);  // ticked before the founder: joins at once, on this tick's key frame
  room.run(45);
  room.reverse_order();
  room.add_viewer(48000);  // ticked after the group encoded: its own frame now, the group's key frame next
  room.add_viewer(48000);  // ready the same tick: shares that key frame
  room.run(300);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(room.sources.shared_encoders(), room.avatars.size()) << "one encoder per face";
  const std::uint64_t sent = room.metrics.avatar_frames_sent.load();
  const std::uint64_t shared = room.metrics.avatar_frames_shared.load();
  EXPECT_GT(shared, sent * 6 / 10) << "of " << sent << " frames";
  for (std::size_t v = 0; v < room.viewers.size(); ++v) {
    EXPECT_GT(room.viewers[v]->frames, 500u) << "viewer " << v;  // 3 faces at 15 Hz or more, 10 s
    for (const std::uint32_t id : room.avatars) EXPECT_LT(smile_error(room, v, id), 0.08f) << "viewer " << v;
  }
}

TEST(SharedEncoders, AJoinerGivesItsWholeGroupOneKeyFrame) {
  ViewedRoom room;
  room.avatars = {1};
  room.add_viewer(48000);
  room.add_viewer(48000);
  room.run(90);
  ASSERT_EQ(room.sources.shared_encoders(), 1u);
  EXPECT_EQ(room.viewers[0]->last_type[1], codec::FrameType::predicted);
  room.add_viewer(48000);  // ticked first: joins on this tick's frame
  room.tick();
  for (std::size_t v = 0; v < 3; ++v) EXPECT_EQ(room.viewers[v]->last_type[1], codec::FrameType::key) << "viewer " << v;
  room.run(30);
  EXPECT_EQ(room.viewers[0]->last_type[1], codec::FrameType::predicted) << "one key frame, not one a tick";
}

TEST(SharedEncoders, AViewerWhoseLinkBacksUpGoesOnAloneAndStillDecodes) {
  ViewedRoom room;
  room.add_viewer(48000);
  room.add_viewer(48000);
  // A link that carries 8 bytes a tick (2 kbit/s) under a budget of 48:
  // it backs up, and its stream holds ticks the others take.
  room.add_viewer(48000, 8);
  room.run(300);
  const std::uint64_t shared_before = room.metrics.avatar_frames_shared.load();
  const std::uint64_t frames_before = room.viewers[0]->frames;
  room.run(300);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(room.metrics.skipped_ticks.load(), 0u) << "the thin link backed up";
  EXPECT_GT(room.viewers[2]->frames, 100u) << "the thin link still gets frames";
  // Every frame of the first viewer's was encoded once for both on good links.
  EXPECT_GE(room.metrics.avatar_frames_shared.load() - shared_before,
            (room.viewers[0]->frames - frames_before) * 9 / 10);
  for (std::size_t v = 0; v < 2; ++v)
    for (const std::uint32_t id : room.avatars) EXPECT_LT(smile_error(room, v, id), 0.08f) << "viewer " << v;
}

TEST(SharedEncoders, AViewerThatVanishesLeavesItsGroupToTheOthers) {
  ViewedRoom room;
  for (int v = 0; v < 3; ++v) room.add_viewer(48000);
  room.run(60);
  const std::uint64_t frames_before = room.viewers[2]->frames;
  room.drop_viewer(0);  // the founder, whose encoder the group took over
  room.run(90);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_GT(room.viewers[2]->frames, frames_before + 100);
  EXPECT_EQ(room.sources.shared_encoders(), room.avatars.size()) << "the two left still share";
  for (std::size_t v = 1; v < 3; ++v)
    for (const std::uint32_t id : room.avatars) EXPECT_LT(smile_error(room, v, id), 0.08f) << "viewer " << v;
}

TEST(SharedEncoders, BudgetsFarApartDoNotShare) {
  ViewedRoom room;
  room.add_viewer(48000);
  room.add_viewer(8000);
  room.run(300);
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(room.metrics.avatar_frames_shared.load(), 0u);
  EXPECT_EQ(room.sources.shared_encoders(), room.avatars.size() * 2);
  // Each stayed within its own budget (ten seconds of it, and the first
  // tick's allowance).
  for (const auto& viewer : room.viewers) {
    EXPECT_GT(viewer->frames, 200u);
    EXPECT_LT(viewer->bytes(), viewer->budget_bps / 8 * 10 + 1000) << viewer->budget_bps;
  }
}

TEST(SharedEncoders, AResyncRequestGivesOnlyThatViewerAKeyFrame) {
  ViewedRoom room;
  room.avatars = {1};
  for (int v = 0; v < 3; ++v) room.add_viewer(48000);
  room.run(90);
  room.viewers[1]->stream.force_key_frames({});
  room.tick();
  EXPECT_EQ(room.viewers[1]->last_type[1], codec::FrameType::key);
  EXPECT_EQ(room.viewers[0]->last_type[1], codec::FrameType::predicted);
  EXPECT_EQ(room.viewers[2]->last_type[1], codec::FrameType::predicted);
  room.run(120);  // it shares again after a while (its group's key frame)
  ASSERT_FALSE(HasFatalFailure());
  EXPECT_EQ(room.sources.shared_encoders(), 1u);
}

TEST(SharedEncoders, AGroupTakesMembersAtMostOnceASecond) {
  SharingKey key{kRoomTickHz, 2, 1};
  codec::EncoderOptions options;
  int a = 0, b = 0, c = 0;
  SharedEncoder group(codec::Encoder(options), key, &a, 10000);
  EXPECT_TRUE(group.takes_members_at(100));
  group.join(&b, 10000, 100);
  EXPECT_TRUE(group.takes_members_at(100)) << "ready the same tick: the same key frame";
  EXPECT_FALSE(group.takes_members_at(101));
  EXPECT_TRUE(group.takes_members_at(100 + kRoomTickHz));
  group.join(&c, 9000, 130);
  EXPECT_EQ(group.target_bps(), 9000) << "the least budget of its members";
  EXPECT_FALSE(group.fits(key, 7000)) << "would lower the others' by more than a fifth";
  EXPECT_FALSE(group.fits(key, 14000)) << "would be held far under its own";
  EXPECT_TRUE(group.fits(key, 12000));
  EXPECT_FALSE(group.fits({kRoomTickHz, 2, 2}, 9000)) << "bundled otherwise";
  group.leave(&c);
  EXPECT_EQ(group.target_bps(), 10000);
}

TEST(SharedEncoders, AGroupOfferedATickOutOfTurnIsBroken) {
  const SharingKey key{kRoomTickHz, 2, 1};
  int a = 0, b = 0;
  codec::FaceSource source, other;
  source.offer(moving_face_of(1, 1));
  other.offer(moving_face_of(1, 1));
  bool reused = false;
  SharedEncoder skipped(codec::Encoder(codec::EncoderOptions{}), key, &a, 10000);
  EXPECT_EQ(skipped.offer(5, source, true, reused), SharedEncoder::Offer::frame);
  source.offer(moving_face_of(1, 2));
  EXPECT_EQ(skipped.offer(7, source, true, reused), SharedEncoder::Offer::diverged) << "tick 6 was missed";
  EXPECT_FALSE(skipped.fits(key, 10000)) << "nobody joins a broken group";

  SharedEncoder taken_over(codec::Encoder(codec::EncoderOptions{}), key, &b, 10000);
  EXPECT_EQ(taken_over.offer(5, source, true, reused), SharedEncoder::Offer::frame);
  EXPECT_EQ(taken_over.offer(5, source, true, reused), SharedEncoder::Offer::frame);
  EXPECT_TRUE(reused);
  EXPECT_EQ(taken_over.offer(5, other, true, reused), SharedEncoder::Offer::diverged)
      << "the same tick number from another room's source";
}

}  // namespace
}  // namespace fw::server
