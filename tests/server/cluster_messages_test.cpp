// What nodes of a cluster say to each other, without Redis: every bridge
// message and the limits news read back as written, and anything else is
// refused rather than misread.
#include <gtest/gtest.h>

#include "bridge_message.hpp"
#include "cluster_keys.hpp"
#include "cluster_limits.hpp"

namespace fw::server {
namespace {

bridge::MemberRecord sample_member() {
  bridge::MemberRecord m;
  m.info.id = 7;
  m.info.name = "Zoé";
  m.info.asset = std::string(32, 'a');
  m.info.preview_bytes = 1200;
  m.info.full_bytes = 90000;
  m.info.seat = {1.5f, -2.f, 300.f, 0.25f};
  m.node = "b";
  m.address = "127.0.0.2";
  m.resume_hash = "hash";
  m.order = (std::uint64_t{1} << 40) + 3;
  return m;
}

TEST(BridgeMessage, AMemberRecordReadsBackAsWritten) {
  const auto bytes = bridge::encode(sample_member());
  const auto back = bridge::decode_member(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->info.name, "Zoé");
  EXPECT_EQ(back->info.seat, sample_member().info.seat);
  EXPECT_EQ(back->order, sample_member().order);
  EXPECT_EQ(back->resume_hash, "hash");
}

TEST(BridgeMessage, FacesGoDownExactly) {
  bridge::Down down{.kind = bridge::DownKind::tick, .owner = "a", .tick = 42};
  codec::FaceParams face;
  face.au[3] = 0.123456789f;
  face.eye_right.pitch_rad = -0.3f;
  face.pallor = 0.5f;
  face.blush[1] = 0.25f;
  down.faces = {{5, face}, {9, codec::FaceParams{}}};
  const auto bytes = bridge::encode(down);
  const auto back = bridge::decode_down(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->tick, 42u);
  ASSERT_EQ(back->faces.size(), 2u);
  EXPECT_EQ(back->faces[0].face.au[3], face.au[3]);
  EXPECT_EQ(back->faces[0].face.eye_right.pitch_rad, -0.3f);
  EXPECT_EQ(back->faces[0].face.blush[1], 0.25f);
  EXPECT_EQ(back->faces[1].id, 9u);
}

TEST(BridgeMessage, EveryKindRoundTripsAndCutsAreRefused) {
  std::vector<bridge::Down> downs = {
      {.kind = bridge::DownKind::roster, .owner = "a", .members = {sample_member()}, .attention = {1, 2}},
      {.kind = bridge::DownKind::joined, .owner = "a", .join_ref = "b/1", .member = sample_member(), .returning = true},
      {.kind = bridge::DownKind::refused, .owner = "a", .join_ref = "b/2", .code = codec::CloseCode::room_full, .reason = "full"},
      {.kind = bridge::DownKind::left, .owner = "a", .avatar = 3},
      {.kind = bridge::DownKind::chat, .owner = "a", .avatar = 0, .message = {9, 8, 7}},
  };
  for (const auto& down : downs) {
    const auto bytes = bridge::encode(down);
    const auto back = bridge::decode_down(bytes.data(), bytes.size());
    ASSERT_TRUE(back) << static_cast<int>(down.kind);
    EXPECT_EQ(back->kind, down.kind);
    EXPECT_EQ(back->join_ref, down.join_ref);
    EXPECT_EQ(back->returning, down.returning);
    EXPECT_EQ(back->members.size(), down.members.size());
    for (std::size_t cut = 0; cut < bytes.size(); ++cut)
      EXPECT_FALSE(bridge::decode_down(bytes.data(), cut)) << "a message cut at " << cut << " was read";
  }
  bridge::Up up{.kind = bridge::UpKind::join, .node = "b", .join_ref = "b/1", .name = "Ann", .asset = "x",
                .address = "::1", .resume_hash = "r", .returning = "k"};
  const auto bytes = bridge::encode(up);
  const auto back = bridge::decode_up(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->returning, "k");
  auto other_version = bytes;
  other_version[0] = bridge::kVersion + 1;
  EXPECT_FALSE(bridge::decode_up(other_version.data(), other_version.size()));
}

TEST(BridgeMessage, RoomStateKeepsMoods) {
  bridge::RoomState state{{{1, {0.1f, 0.f, -0.2f, 0.f, 0.f, 0.3f}}}};
  const auto bytes = bridge::encode(state);
  const auto back = bridge::decode_state(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->moods.at(0).values, state.moods[0].values);
}

TEST(ClusterLimits, NewsReadsBackAndJunkIsRefused) {
  LimitsNews news{.node = "a", .beat = true};
  news.spent = {{"127.0.0.1", AddressRate::join, 2}, {"2001:db8::/64", AddressRate::chat, 1.5}};
  news.connections = {{"127.0.0.1", 3}};
  news.tokens = {{"h1", "r1", ""}, {"h2", "", ""}, {"h3", "r3", "b"}};
  const auto back = decode_limits(encode_limits(news));
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->beat);
  ASSERT_EQ(back->spent.size(), 2u);
  EXPECT_EQ(back->spent[1].key, "2001:db8::/64");
  EXPECT_EQ(back->spent[1].tokens, 1.5);
  EXPECT_EQ(back->connections.at("127.0.0.1"), 3u);
  ASSERT_EQ(back->tokens.size(), 3u);
  EXPECT_TRUE(back->tokens[1].resume_hash.empty());
  EXPECT_EQ(back->tokens[2].taken_from, "b");
  EXPECT_FALSE(decode_limits("hello"));
  EXPECT_FALSE(decode_limits("node a\ns 9 1 x\n"));
  EXPECT_FALSE(decode_limits("node a\nz\n"));
}

TEST(ClusterKeys, RoomChannelsNameTheirRoom) {
  EXPECT_EQ(cluster_keys::parse_room_channel(cluster_keys::room_down("meet")).room, "meet");
  EXPECT_TRUE(cluster_keys::parse_room_channel(cluster_keys::room_down("a:up")).down);
  EXPECT_EQ(cluster_keys::parse_room_channel(cluster_keys::room_up("x")).room, "x");
  EXPECT_TRUE(cluster_keys::parse_room_channel("fw:limits").room.empty());
}

}  // namespace
}  // namespace fw::server
