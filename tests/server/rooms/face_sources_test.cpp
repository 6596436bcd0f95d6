// FaceSources without sockets: a viewer whose encoders read the room's
// shared face sources receives byte for byte the stream it received when
// each encoder worked the face out itself, through joins, a face that
// leaves and comes back, thin budgets (bundled ticks) and a congested link
// (held ticks).
#include "face_sources.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "draining_connection.hpp"
#include "metrics.hpp"
#include "subscriber_stream.hpp"

namespace fw::server {
namespace {

using test::DrainingConnection;
using test::kRoomTickHz;
using test::kRoomTickUs;
using test::moving_face_of;

/// Two viewers alike but for where their encoders read the faces from.
struct Pair {
  Pair(std::uint32_t budget_bps, std::size_t drain_per_tick)
      : with_sources(std::make_shared<DrainingConnection>(drain_per_tick)),
        alone(std::make_shared<DrainingConnection>(drain_per_tick)),
        shared_stream(settings(budget_bps), with_sources, metrics),
        own_stream(settings(budget_bps), alone, metrics) {}

  static StreamSettings settings(std::uint32_t budget_bps) {
    StreamSettings s;
    s.tick_hz = kRoomTickHz;
    s.budget_bps = budget_bps;
    s.packages = false;
    return s;
  }
  void add(std::uint32_t avatar) {
    shared_stream.add_avatar(avatar, nullptr, nullptr);
    own_stream.add_avatar(avatar, nullptr, nullptr);
  }
  void remove(std::uint32_t avatar) {
    shared_stream.remove_avatar(avatar);
    own_stream.remove_avatar(avatar);
  }
  void tick(const std::vector<std::uint32_t>& avatars) {
    ++tick_index;
    std::vector<codec::FaceParams> faces;
    faces.reserve(avatars.size());
    for (const std::uint32_t id : avatars) faces.push_back(moving_face_of(id, tick_index));
    std::vector<AvatarFace> plain;
    for (std::size_t i = 0; i < avatars.size(); ++i) plain.push_back({avatars[i], &faces[i]});
    std::vector<AvatarFace> sourced = plain;
    sources.offer(sourced);
    now_us += kRoomTickUs;
    shared_stream.tick(tick_index, now_us, sourced);
    own_stream.tick(tick_index, now_us, plain);
    with_sources->drain_a_tick();
    alone->drain_a_tick();
  }
  void expect_same_bytes() const {
    ASSERT_EQ(with_sources->messages().size(), alone->messages().size());
    for (std::size_t i = 0; i < alone->messages().size(); ++i)
      ASSERT_EQ(*with_sources->messages()[i], *alone->messages()[i]) << "message " << i;
  }

  Metrics metrics;
  std::shared_ptr<DrainingConnection> with_sources, alone;
  SubscriberStream shared_stream, own_stream;
  FaceSources sources;
  std::uint32_t tick_index = 0;
  std::uint64_t now_us = 1;
};

TEST(FaceSources, AViewerReceivesTheSameBytesWithTheRoomsSharedFaceSources) {
  Pair pair(24000, 1'000'000);
  pair.add(1);
  pair.add(2);
  for (int i = 0; i < 90; ++i) pair.tick({1, 2});
  pair.add(3);  // joins mid-stream: its encoder starts with no history of its own
  for (int i = 0; i < 90; ++i) pair.tick({1, 2, 3});
  pair.remove(2);  // leaves, and comes back with a fresh encoder
  for (int i = 0; i < 30; ++i) pair.tick({1, 3});
  pair.add(2);
  for (int i = 0; i < 90; ++i) pair.tick({1, 2, 3});
  EXPECT_EQ(pair.sources.size(), 3u);
  EXPECT_GT(pair.alone->messages().size(), 200u) << "frames went out";
  pair.expect_same_bytes();
}

TEST(FaceSources, AThinCongestedViewerReceivesTheSameBytesToo) {
  // 3 kbit/s for 4 faces bundles frames on every second tick; a socket that
  // drains 8 bytes a tick backs up, and the stream holds ticks.
  Pair pair(3000, 8);
  for (std::uint32_t id = 1; id <= 4; ++id) pair.add(id);
  for (int i = 0; i < 600; ++i) pair.tick({1, 2, 3, 4});
  EXPECT_GT(pair.metrics.skipped_ticks.load(), 0u) << "the link backed up";
  pair.expect_same_bytes();
}

TEST(FaceSources, ASourceGoesWithItsFace) {
  FaceSources sources;
  codec::FaceParams a, b;
  std::vector<AvatarFace> faces = {{1, &a}, {2, &b}};
  sources.offer(faces);
  ASSERT_NE(faces[0].source, nullptr);
  EXPECT_NE(faces[0].source, faces[1].source);
  EXPECT_EQ(faces[0].source->ticks(), 1u);
  sources.offer(faces);
  EXPECT_EQ(faces[1].source->ticks(), 2u);
  std::vector<AvatarFace> fewer = {{2, &b}};
  sources.offer(fewer);
  EXPECT_EQ(sources.size(), 1u);
  std::vector<AvatarFace> back = {{1, &a}, {2, &b}};
  sources.offer(back);
  EXPECT_EQ(back[0].source->ticks(), 1u) << "a face that comes back starts afresh";
  EXPECT_EQ(back[1].source->ticks(), 4u);
}

}  // namespace
}  // namespace fw::server
