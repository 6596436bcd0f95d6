// What nodes of a cluster say to each other, without Redis: every bridge
// message and the limits news read back as written, and anything else is
// refused rather than misread.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "address_limits.hpp"
#include "fw/codec/byte_writer.hpp"
#include "bridge_message.hpp"
#include "cluster_keys.hpp"
#include "cluster_limits.hpp"
#include "cluster_message_check.hpp"
#include "sample_messages.hpp"

namespace fw::server {
namespace {

/// An avatar's redefined units as the owner encodes them (PROTOCOL.md 5.17).
bridge::Bytes unit_morphs_of(std::uint32_t avatar, codec::UnitMorphs set = test::sample_unit_morphs()) {
  set.avatar = avatar;
  bridge::Bytes bytes;
  codec::write_message(set, bytes);
  return bytes;
}

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
  m.language = "de";
  m.order = (std::uint64_t{1} << 40) + 3;
  m.unit_morphs = unit_morphs_of(7);
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
  EXPECT_EQ(back->language, "de") << "a successor says the person's lines in their language";
  EXPECT_EQ(back->unit_morphs, unit_morphs_of(7)) << "a successor gives the avatar its redefined units back";
  bridge::MemberRecord none = sample_member();
  none.unit_morphs.clear();
  const auto plain = bridge::encode(none);
  EXPECT_TRUE(bridge::decode_member(plain.data(), plain.size())->unit_morphs.empty());
}

TEST(BridgeMessage, FacesGoDownExactly) {
  bridge::Down down{.kind = bridge::DownKind::tick, .owner = "a", .tick = 42};
  codec::FaceParams face;
  face.au[3] = 0.123456789f;
  face.eye_right.pitch_rad = -0.3f;
  face.pallor = 0.5f;
  face.blush[1] = 0.25f;
  face.corrective = {0.5f, -0.25f, 0.0f, 1.0f, -1.0f, 0.015625f};  // the physics face's, to every node's encoders
  down.faces = {{5, face}, {9, codec::FaceParams{}}};
  const auto bytes = bridge::encode(down);
  const auto back = bridge::decode_down(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->tick, 42u);
  ASSERT_EQ(back->faces.size(), 2u);
  EXPECT_EQ(back->faces[0].face.au[3], face.au[3]);
  EXPECT_EQ(back->faces[0].face.eye_right.pitch_rad, -0.3f);
  EXPECT_EQ(back->faces[0].face.blush[1], 0.25f);
  EXPECT_EQ(back->faces[0].face.corrective, face.corrective);
  EXPECT_EQ(back->faces[1].id, 9u);
}

TEST(BridgeMessage, EveryKindRoundTripsAndCutsAreRefused) {
  std::vector<bridge::Down> downs = {
      {.kind = bridge::DownKind::roster, .owner = "a", .members = {sample_member()}, .attention = {1, 2}},
      {.kind = bridge::DownKind::joined, .owner = "a", .join_ref = "b/1", .member = sample_member(), .returning = true},
      {.kind = bridge::DownKind::refused, .owner = "a", .join_ref = "b/2", .code = codec::CloseCode::room_full, .reason = "full"},
      {.kind = bridge::DownKind::left, .owner = "a", .avatar = 3},
      {.kind = bridge::DownKind::chat, .owner = "a", .avatar = 0, .message = {9, 8, 7}},
      {.kind = bridge::DownKind::speaking, .owner = "a", .avatar = 0, .message = {6, 5}},
      {.kind = bridge::DownKind::unit_morphs, .owner = "a", .avatar = 7, .message = unit_morphs_of(7)},
  };
  for (const auto& down : downs) {
    const auto bytes = bridge::encode(down);
    const auto back = bridge::decode_down(bytes.data(), bytes.size());
    ASSERT_TRUE(back) << static_cast<int>(down.kind);
    EXPECT_EQ(back->kind, down.kind);
    EXPECT_EQ(back->join_ref, down.join_ref);
    EXPECT_EQ(back->returning, down.returning);
    EXPECT_EQ(back->members.size(), down.members.size());
    EXPECT_EQ(back->avatar, down.avatar);
    EXPECT_EQ(back->message, down.message);
    if (!down.members.empty()) {
      EXPECT_EQ(back->members[0].unit_morphs, down.members[0].unit_morphs);
    }
    for (std::size_t cut = 0; cut < bytes.size(); ++cut)
      EXPECT_FALSE(bridge::decode_down(bytes.data(), cut)) << "a message cut at " << cut << " was read";
  }
  bridge::Up up{.kind = bridge::UpKind::join, .node = "b", .join_ref = "b/1", .name = "Ann", .asset = "x",
                .address = "::1", .resume_hash = "r", .returning = "k", .language = "pt-br"};
  const auto bytes = bridge::encode(up);
  const auto back = bridge::decode_up(bytes.data(), bytes.size());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->returning, "k");
  EXPECT_EQ(back->language, "pt-br") << "a person's language travels with the join";
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


// ---- What is read from Redis is checked like what a client sends ----------

template <class Message>
bridge::Bytes client_message(const Message& message) {
  bridge::Bytes bytes;
  codec::write_message(message, bytes);
  return bytes;
}

bridge::Bytes attention_bytes() { return client_message(codec::Attention{{{7, codec::AttentionTarget::room, 0}}}); }

/// One message of each kind as an owner sends them.
std::vector<bridge::Down> owners_news() {
  codec::FaceParams face;
  face.au[0] = 0.5f;
  face.head_yaw_rad = -0.4f;
  face.head_translation_mm[2] = 12.f;
  return {
      {.kind = bridge::DownKind::roster, .owner = "a", .members = {sample_member()}, .attention = attention_bytes()},
      {.kind = bridge::DownKind::joined, .owner = "a", .join_ref = "b/1", .member = sample_member()},
      {.kind = bridge::DownKind::refused, .owner = "a", .join_ref = "b/2", .code = codec::CloseCode::room_full,
       .reason = "room 'meet' is full"},
      {.kind = bridge::DownKind::left, .owner = "a", .avatar = 3},
      {.kind = bridge::DownKind::seats, .owner = "a", .message = client_message(codec::Seats{{{7, {1, 2, 3, 0.5f}}}})},
      {.kind = bridge::DownKind::attention, .owner = "a", .attention = attention_bytes()},
      {.kind = bridge::DownKind::chat, .owner = "a", .avatar = 0, .message = client_message(codec::Chat{7, "hi there"})},
      {.kind = bridge::DownKind::result, .owner = "a", .avatar = 7, .message = client_message(codec::CommandResult{4, ""})},
      {.kind = bridge::DownKind::speaking, .owner = "a", .avatar = 0,
       .message = client_message(codec::Speaking{7, 90, 1800, "de", "guten Tag"})},
      {.kind = bridge::DownKind::unit_morphs, .owner = "a", .avatar = 7, .message = unit_morphs_of(7)},
      {.kind = bridge::DownKind::tick, .owner = "a", .tick = 9, .faces = {{7, face}, {8, codec::FaceParams{}}}},
  };
}

bridge::Up bridges_join() {
  return {.kind = bridge::UpKind::join, .node = "b", .join_ref = "b/1", .name = "Ann", .asset = std::string(32, 'c'),
          .address = "127.0.2.9", .resume_hash = "qPZ1-0_abc", .returning = "", .language = "de"};
}

std::vector<bridge::Up> bridges_requests() {
  codec::Command command;
  command.request_id = 3;
  command.emotion = "joy";
  return {
      bridge::up_sync("b"), bridges_join(), bridge::up_leave("b", 7), bridge::up_chat("b", 7, "hello, room"),
      bridge::up_command("b", 7, client_message(command)),
  };
}

TEST(ClusterCheck, WhatNodesSendIsBelieved) {
  for (bridge::Down down : owners_news()) {
    const auto why = cluster_check::refusal_of(down);
    EXPECT_FALSE(why) << static_cast<int>(down.kind) << ": " << why.value_or("");
  }
  for (const bridge::Up& up : bridges_requests()) {
    const auto why = cluster_check::refusal_of(up);
    EXPECT_FALSE(why) << static_cast<int>(up.kind) << ": " << why.value_or("");
  }
  LimitsNews news{.node = "node-2.example:8080", .beat = true};
  news.spent = {{"127.0.1.5", AddressRate::join, 20}, {"2001:db8:1:2::/64", AddressRate::chat, 1.5}};
  news.connections = {{"127.0.1.5", 3}};
  news.tokens = {{"h1", "r1", ""}, {"h2", "", ""}, {"h3", "r3", "a"}};
  EXPECT_FALSE(cluster_check::refusal_of(news, AbuseLimits{}));
}

/// `forge` applied to the owner's message of `kind` makes it refused.
template <class Forge>
void expect_refused(bridge::DownKind kind, Forge forge, const std::string& what) {
  for (bridge::Down down : owners_news())
    if (down.kind == kind) {
      forge(down);
      EXPECT_TRUE(cluster_check::refusal_of(down)) << what << " was believed";
      // And it is refused after travelling as bytes too (what Redis carries).
      const auto bytes = bridge::encode(down);
      if (auto read = bridge::decode_down(bytes.data(), bytes.size())) {
        EXPECT_TRUE(cluster_check::refusal_of(*read)) << what;
      }
    }
}

TEST(ClusterCheck, ForgedNewsOfEveryKindIsRefused) {
  using K = bridge::DownKind;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  expect_refused(K::roster, [](auto& m) { m.owner = ""; }, "news from no node");
  expect_refused(K::roster, [](auto& m) { m.owner = "a b\n"; }, "news from a node name --node refuses");
  expect_refused(K::roster, [](auto& m) { m.members.assign(65, sample_member()); }, "a roster past a room's size");
  expect_refused(K::roster, [](auto& m) { m.members.push_back(sample_member()); }, "a roster with one id twice");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.name = "\u202Eevil"; }, "a bidi override in a name");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.name = ""; }, "an empty name");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.name = std::string(33, 'x'); }, "a name past 32 bytes");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.id = 0; }, "avatar id 0");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.id = 1u << 21; }, "an avatar id past 21 bits");
  expect_refused(K::roster, [&](auto& m) { m.members[0].info.seat.x_mm = nan; }, "a seat at NaN");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.seat.z_mm = 1e9f; }, "a seat off the table");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.asset = "../../etc/passwd"; }, "an asset id with a path");
  expect_refused(K::roster, [](auto& m) { m.members[0].info.full_bytes = 0xffffffffu; }, "a 4 GB package");
  expect_refused(K::roster, [](auto& m) { m.members[0].address = "not an address"; }, "a member's address");
  expect_refused(K::roster, [](auto& m) { m.members[0].language = "de\n"; }, "a member's language with a line feed");
  expect_refused(K::roster, [](auto& m) { m.attention = {1, 2, 3}; }, "a roster whose attention is junk");
  expect_refused(K::joined, [](auto& m) { m.member.info.name = "a\x07"; }, "a control character in a name");
  expect_refused(K::joined, [](auto& m) { m.join_ref = std::string(200, 'r'); }, "a join reference of 200 bytes");
  expect_refused(K::refused, [](auto& m) { m.code = static_cast<codec::CloseCode>(999); }, "an unknown close code");
  expect_refused(K::refused, [](auto& m) { m.reason = std::string(121, 'r'); }, "a reason past 120 bytes");
  expect_refused(K::refused, [](auto& m) { m.reason = "bad\x1b[2J"; }, "an escape sequence in a reason");
  expect_refused(K::left, [](auto& m) { m.avatar = 0; }, "avatar 0 leaving");
  expect_refused(K::seats, [](auto& m) { m.message = {0xff, 0x00}; }, "seats that are junk");
  expect_refused(K::attention, [](auto& m) { m.attention = client_message(codec::Chat{7, "hi"}); }, "attention that is a chat line");
  expect_refused(K::chat, [](auto& m) { m.message = client_message(codec::Seats{}); }, "chat that is no chat line");
  expect_refused(K::chat, [](auto& m) { m.message = client_message(codec::Chat{7, ""}); }, "an empty chat line");
  expect_refused(K::chat, [](auto& m) {
    m.message = {0x80 | static_cast<std::uint8_t>(codec::MessageType::chat), 7, 2, 'a', 0x07};
  }, "a chat line with a control character");
  expect_refused(K::result, [](auto& m) { m.message = client_message(codec::Chat{7, "hi"}); }, "a result that is chat");
  expect_refused(K::result, [](auto& m) { m.avatar = 0; }, "a result for nobody");
  expect_refused(K::speaking, [](auto& m) { m.message = client_message(codec::Chat{7, "hi"}); }, "speaking that is chat");
  expect_refused(K::speaking, [](auto& m) { m.message = client_message(codec::Speaking{0, 1, 1, "de", "a"}); },
                 "speaking of avatar 0");
  expect_refused(K::speaking, [](auto& m) { m.avatar = 7; }, "speaking for one person only");
  expect_refused(K::roster, [](auto& m) { m.members[0].unit_morphs = {1, 2, 3}; }, "a member's set that is junk");
  expect_refused(K::roster, [](auto& m) { m.members[0].unit_morphs = unit_morphs_of(8); }, "a member's set of another");
  expect_refused(K::joined, [](auto& m) { m.member.unit_morphs = client_message(codec::Chat{7, "hi"}); },
                 "a member's set that is chat");
  expect_refused(K::unit_morphs, [](auto& m) { m.avatar = 0; }, "a set of avatar 0");
  expect_refused(K::unit_morphs, [](auto& m) { m.avatar = 8; }, "a set that names another avatar than its news");
  expect_refused(K::unit_morphs, [](auto& m) { m.message = client_message(codec::Chat{7, "hi"}); }, "a set that is chat");
  expect_refused(K::unit_morphs, [](auto& m) { m.message.push_back(0); }, "a set with a byte more");
  auto forged_set = [](auto change) {
    codec::UnitMorphs set = test::sample_unit_morphs();
    set.avatar = 7;
    change(set);
    // Laid out as 5.17 says, by hand: the codec's writer asserts what a forger ignores.
    bridge::Bytes bytes;
    codec::ByteWriter w(bytes);
    w.u8(0x80 | static_cast<std::uint8_t>(codec::MessageType::unit_morphs));
    w.varint(set.avatar);
    w.varint(set.version);
    w.u8(static_cast<std::uint8_t>(set.units.size()));
    for (const auto& unit : set.units) {
      w.u8(unit.channel);
      w.varint(static_cast<std::uint32_t>(unit.moves.size()));
      for (const auto& move : unit.moves) {
        w.varint(move.vertex);
        for (const std::int16_t d : move.delta) w.i16_le(d);
      }
    }
    return bytes;
  };
  {
    bridge::Down laid{.kind = K::unit_morphs, .owner = "a", .avatar = 7, .message = forged_set([](auto&) {})};
    EXPECT_EQ(laid.message, unit_morphs_of(7)) << "the forger's layout is the codec's";
    EXPECT_FALSE(cluster_check::refusal_of(laid));
  }
  expect_refused(K::unit_morphs, [&](auto& m) { m.message = forged_set([](auto& s) { s.version = 0; }); },
                 "a set of version 0");
  expect_refused(K::unit_morphs, [&](auto& m) {
    m.message = forged_set([](auto& s) { s.units.resize(codec::kMaxRedefinedChannels + 1); });
  }, "a set of 9 channels");
  expect_refused(K::unit_morphs, [&](auto& m) {
    m.message = forged_set([](auto& s) {
      s.units.resize(1);
      s.units[0].moves.clear();
      for (std::uint32_t v = 0; v <= codec::kMaxUnitMorphMoves; ++v) s.units[0].moves.push_back({v, {1, 1, 1}});
    });
  }, "a unit of 1025 moves");
  expect_refused(K::unit_morphs, [&](auto& m) { m.message = forged_set([](auto& s) { s.units[2].channel = 29; }); },
                 "channel 29");
  expect_refused(K::unit_morphs, [&](auto& m) { m.message = forged_set([](auto& s) { s.units[1].channel = 0; }); },
                 "a channel twice");
  expect_refused(K::unit_morphs, [&](auto& m) {
    m.message = forged_set([](auto& s) { std::swap(s.units[0].moves[0], s.units[0].moves[1]); });
  }, "vertices not increasing");
  expect_refused(K::tick, [&](auto& m) { m.faces[0].face.au[3] = nan; }, "a face with NaN");
  expect_refused(K::tick, [&](auto& m) { m.faces[0].face.head_pitch_rad = inf; }, "a face with infinity");
  expect_refused(K::tick, [](auto& m) { m.faces[0].face.head_yaw_rad = 100.f; }, "a head turned 100 rad");
  expect_refused(K::tick, [](auto& m) { m.faces[1].face.blush[2] = -3.f; }, "negative blush");
  expect_refused(K::tick, [](auto& m) { m.faces[1].face.eye_left.yaw_rad = 5.f; }, "an eye turned 5 rad");
  expect_refused(K::tick, [](auto& m) { m.faces[1].id = 7; }, "a tick with one face twice");
  expect_refused(K::tick, [](auto& m) { m.faces[1].id = 0; }, "a face of avatar 0");
  expect_refused(K::tick, [](auto& m) { m.faces.resize(65, m.faces[0]); }, "more faces than a room holds");
}

TEST(ClusterCheck, FacesAHairOutOfRangeAreClampedNotRefused) {
  bridge::Down tick = owners_news().back();
  ASSERT_EQ(tick.kind, bridge::DownKind::tick);
  tick.faces[0].face.au[0] = 1.02f;          // physics overshoots a little
  tick.faces[0].face.head_yaw_rad = -1.25f;  // range [-1.2, 1.2]
  EXPECT_FALSE(cluster_check::refusal_of(tick));
  EXPECT_EQ(tick.faces[0].face.au[0], 1.f);
  EXPECT_NEAR(tick.faces[0].face.head_yaw_rad, -1.2f, 0.01f);
  EXPECT_EQ(tick.faces[0].face.head_translation_mm[2], 12.f) << "values in range are left alone";
  // An eye turns past its own range to counter the head (the codec carries
  // eye plus head): the owner's simulation does so, and it goes through as it is.
  tick.faces[1].face.eye_left.yaw_rad = -0.9f;
  tick.faces[1].face.eye_right.pitch_rad = 0.75f;
  EXPECT_FALSE(cluster_check::refusal_of(tick));
  EXPECT_EQ(tick.faces[1].face.eye_left.yaw_rad, -0.9f);
  EXPECT_EQ(tick.faces[1].face.eye_right.pitch_rad, 0.75f);
}

TEST(ClusterCheck, ForgedRequestsOfEveryKindAreRefused) {
  auto refused = [](bridge::Up up) { return cluster_check::refusal_of(up).has_value(); };
  auto join = bridges_join();
  EXPECT_TRUE(refused([&] { auto m = join; m.join_ref = "c/1"; return m; }())) << "a join numbered by another node";
  EXPECT_TRUE(refused([&] { auto m = join; m.name = "\u200BAda"; return m; }())) << "a zero-width character in a name";
  EXPECT_TRUE(refused([&] { auto m = join; m.address = "10.0.0.1; rm"; return m; }())) << "a malformed address";
  EXPECT_TRUE(refused([&] { auto m = join; m.address = ""; return m; }())) << "a join from no address";
  EXPECT_TRUE(refused([&] { auto m = join; m.asset = std::string(65, 'a'); return m; }())) << "a 65-byte asset id";
  EXPECT_TRUE(refused([&] { auto m = join; m.returning = std::string(65, 'k'); return m; }())) << "a long resume key";
  EXPECT_TRUE(refused([&] { auto m = join; m.node = ""; return m; }())) << "a join from no node";
  EXPECT_TRUE(refused([&] { auto m = join; m.language = "DE"; return m; }())) << "a language no hello carries";
  EXPECT_TRUE(refused([&] { auto m = join; m.language = std::string(17, 'a'); return m; }())) << "a 17-byte language";
  EXPECT_TRUE(refused(bridge::up_leave("b", 0))) << "avatar 0 leaving";
  EXPECT_TRUE(refused(bridge::up_chat("b", 7, ""))) << "an empty chat line";
  EXPECT_TRUE(refused(bridge::up_chat("b", 7, std::string(501, 'x')))) << "a chat line past 500 bytes";
  EXPECT_TRUE(refused(bridge::up_chat("b", 7, "ring\x07"))) << "a control character in chat";
  EXPECT_TRUE(refused(bridge::up_chat("b", 7, "\xff\xfe"))) << "chat that is not UTF-8";
  EXPECT_TRUE(refused(bridge::up_chat("b", 0, "hi"))) << "chat from avatar 0";
  EXPECT_TRUE(refused(bridge::up_command("b", 7, {1, 2, 3}))) << "a command that is junk";
  EXPECT_TRUE(refused(bridge::up_sync(std::string(65, 'n')))) << "a node name past 64 bytes";
}

TEST(ClusterCheck, ARoomsRecordIsCheckedBeforeATakeoverRestoresIt) {
  EXPECT_FALSE(cluster_check::refusal_of(sample_member()));
  auto forged = sample_member();
  forged.info.seat.facing_yaw_rad = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(cluster_check::refusal_of(forged));
  bridge::RoomState moods{{{1, {0.1f, 0.f, -0.2f}}, {2, {0.f}}}};
  EXPECT_FALSE(cluster_check::refusal_of(moods));
  moods.moods[1].values[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(cluster_check::refusal_of(moods)) << "a NaN mood would stay NaN through the simulation's clamp";
  moods.moods[1] = {1, {0.f}};
  EXPECT_TRUE(cluster_check::refusal_of(moods)) << "one face's mood twice";
}

TEST(ClusterCheck, ForgedLimitsNewsIsRefused) {
  const AbuseLimits limits;
  auto refused = [&](auto forge) {
    LimitsNews news{.node = "b", .beat = true};
    news.spent = {{"127.0.1.5", AddressRate::join, 2}};
    news.connections = {{"127.0.1.5", 3}};
    forge(news);
    return cluster_check::refusal_of(news, limits).has_value();
  };
  EXPECT_FALSE(refused([](LimitsNews&) {}));
  EXPECT_TRUE(refused([](LimitsNews& n) { n.node = "evil node"; }));
  EXPECT_TRUE(refused([](LimitsNews& n) { n.spent[0].tokens = std::numeric_limits<double>::quiet_NaN(); }));
  EXPECT_TRUE(refused([](LimitsNews& n) { n.spent[0].tokens = std::numeric_limits<double>::infinity(); }));
  EXPECT_TRUE(refused([](LimitsNews& n) { n.spent[0].tokens = 1e12; })) << "a trillion joins in one beat";
  EXPECT_TRUE(refused([](LimitsNews& n) { n.spent[0].key = "x\ny"; }));
  EXPECT_TRUE(refused([&](LimitsNews& n) { n.connections["127.0.1.6"] = limits.connections_per_address + 1; }))
      << "more connections than the address may hold";
  EXPECT_TRUE(refused([](LimitsNews& n) {
    for (int i = 0; i < 70000; ++i)
      n.connections["10." + std::to_string(i / 65536) + "." + std::to_string(i / 256 % 256) + "." + std::to_string(i % 256)] = 1;
  })) << "more addresses than a node holds connections";
  EXPECT_TRUE(refused([](LimitsNews& n) { n.tokens = {{"", "r", ""}}; })) << "a token without its hash";
  // What the text form cannot carry is refused when read already.
  EXPECT_FALSE(decode_limits("node b\ns 0 -5 127.0.1.5\n"));
}

// ---- What another node says of an address expires -------------------------

using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

TEST(RemoteLimits, SpendingOnAnotherNodeCountsHere) {
  AddressLimits limits{AbuseLimits{}};
  const auto now = Clock::now();
  limits.charge(AddressRate::join, "127.0.1.5", 20, now, 3s);  // its whole burst, honestly spent on another node
  EXPECT_TRUE(limits.take(AddressRate::join, "127.0.1.5", now)) << "the address joined here as well";
  EXPECT_FALSE(limits.take(AddressRate::join, "127.0.2.5", now)) << "another address paid for it";
}

TEST(RemoteLimits, ForgedSpendingBlocksAnAddressForAFewSecondsAtMost) {
  AddressLimits limits{AbuseLimits{}};
  const auto now = Clock::now();
  // Uploads refill one token in 10 s: a forged report that emptied the
  // bucket would block the address's uploads for 10 s, at every report.
  for (const auto rate : {AddressRate::upload, AddressRate::room_creation, AddressRate::join, AddressRate::chat})
    limits.charge(rate, "127.0.1.5", 1e9, now, 3s);
  for (const auto rate : {AddressRate::upload, AddressRate::room_creation, AddressRate::join, AddressRate::chat}) {
    const auto wait = limits.take(rate, "127.0.1.5", now);
    ASSERT_TRUE(wait) << "the report was not counted at all";
    EXPECT_LE(*wait, 3.0 + 1e-9) << "a report made the address wait " << *wait << " s";
    EXPECT_FALSE(limits.take(rate, "127.0.1.5", now + 3100ms)) << "the address is still blocked 3 s after the report";
  }
  // What was taken here stays taken: a report never gives tokens back.
  AddressLimits spent{AbuseLimits{}};
  for (int i = 0; i < 6; ++i) ASSERT_FALSE(spent.take(AddressRate::upload, "127.0.1.6", now));
  spent.charge(AddressRate::upload, "127.0.1.6", 1, now, 3s);
  EXPECT_TRUE(spent.take(AddressRate::upload, "127.0.1.6", now + 3100ms)) << "a report refilled the bucket";
}

TEST(RemoteLimits, ConnectionsCountUntilTheirNewsExpires) {
  AbuseLimits cap;
  cap.connections_per_address = 4;
  AddressLimits limits{cap};
  const auto now = Clock::now();
  limits.set_remote_connections("b", {{"127.0.1.5", 1'000'000}}, now, now + 1h);
  EXPECT_FALSE(limits.open_connection("127.0.1.5")) << "the other node holds the address's share";
  EXPECT_TRUE(limits.open_connection("127.0.2.5")) << "another address is not held";
  // News that expired counts no more: the node stopped saying it.
  limits.set_remote_connections("b", {{"127.0.1.5", 1'000'000}}, now - 10s, now - 7s);
  EXPECT_TRUE(limits.open_connection("127.0.1.5")) << "expired news still blocks the address";
  // A count past the share counts as the share: other nodes' counts add up.
  limits.set_remote_connections("c", {{"127.0.3.5", 1'000'000}}, now, now + 1h);
  limits.set_remote_connections("d", {{"127.0.3.5", 1}}, now, now + 1h);
  EXPECT_FALSE(limits.open_connection("127.0.3.5"));
  limits.set_remote_connections("c", {}, now, now + 1h);
  EXPECT_TRUE(limits.open_connection("127.0.3.5")) << "a node that holds none frees the share";
}

TEST(RemoteLimits, NewsFromManyNodesIsBounded) {
  AbuseLimits many;
  many.connections_per_address = 1000;
  AddressLimits limits{many};
  const auto now = Clock::now();
  for (int i = 0; i < 600; ++i) limits.set_remote_connections("n" + std::to_string(i), {{"127.0.1.5", 1}}, now, now + 1h);
  int opened = 0;
  while (opened < 1000 && limits.open_connection("127.0.1.5")) ++opened;
  EXPECT_EQ(opened, 1000 - static_cast<int>(AddressLimits::kMaxRemoteNodes))
      << "news from more nodes than a cluster has was kept";
}

}  // namespace
}  // namespace fw::server
