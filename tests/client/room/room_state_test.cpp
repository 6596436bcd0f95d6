#include "room_state.hpp"

#include <gtest/gtest.h>

#include "server_messages.hpp"

namespace fw::client {
namespace {

using namespace fw::client::test;
using Quality = codec::PackageChunk::Quality;
using Clock = std::chrono::steady_clock;

codec::Welcome welcome_of(std::uint32_t you, std::vector<codec::AvatarInfo> avatars) {
  codec::Welcome welcome;
  welcome.you = you;
  welcome.room = "lobby";
  welcome.tick_hz = 30;
  welcome.avatars = std::move(avatars);
  return welcome;
}

AssembledPackage package(std::uint32_t avatar, Quality quality, std::uint8_t fill) {
  return {avatar, quality, Bytes(10, fill)};
}

TEST(RoomState, AWelcomeKeepsThePackagesOfAvatarsStillHereUnderTheSameAsset) {
  RoomState state;
  const auto now = Clock::now();
  state.welcomed(welcome_of(1, {avatar_info(1, "ada", "a1"), avatar_info(2, "bob", "b1"), avatar_info(3, "cyd")}), {}, now);
  EXPECT_TRUE(state.package_arrived(package(2, Quality::full, 2), now));
  EXPECT_TRUE(state.package_arrived(package(3, Quality::full, 3), now));
  // After a reconnection: bob has a new face, cyd's has no asset to compare.
  state.welcomed(welcome_of(1, {avatar_info(1, "ada", "a1"), avatar_info(2, "bob", "b2"), avatar_info(3, "cyd")}), {}, now);
  EXPECT_FALSE(state.avatars.at(2).package) << "another asset: its package must come again";
  EXPECT_FALSE(state.avatars.at(3).package);
  EXPECT_TRUE(state.package_arrived(package(2, Quality::full, 4), now));
  state.welcomed(welcome_of(1, {avatar_info(2, "bob", "b2")}), {}, now);
  ASSERT_TRUE(state.avatars.at(2).package);
  EXPECT_EQ(*state.avatars.at(2).package, Bytes(10, 4));
  EXPECT_EQ(state.avatars.size(), 1u) << "who is not in the welcome has gone";
  EXPECT_TRUE(state.joined);
}

TEST(RoomState, TheOwnUploadedPackageIsTheOwnFace) {
  RoomState state;
  const auto own = std::make_shared<const Bytes>(Bytes{1, 2});
  state.welcomed(welcome_of(4, {avatar_info(4, "me", "mine")}), own, Clock::now());
  EXPECT_EQ(state.avatars.at(4).package, own);
  EXPECT_EQ(state.avatars.at(4).package_quality, Quality::full);
  EXPECT_EQ(state.avatars.at(4).package_serial, 1u);
}

TEST(RoomState, APackageReplacesThePreviewButNotTheOtherWayRound) {
  RoomState state;
  const auto now = Clock::now();
  state.welcomed(welcome_of(1, {avatar_info(2, "bob")}), {}, now);
  EXPECT_FALSE(state.package_arrived(package(9, Quality::full, 1), now)) << "not in the room";
  EXPECT_TRUE(state.package_arrived(package(2, Quality::preview, 1), now));
  EXPECT_TRUE(state.package_arrived(package(2, Quality::full, 2), now));
  EXPECT_FALSE(state.package_arrived(package(2, Quality::preview, 3), now));
  EXPECT_EQ(*state.avatars.at(2).package, Bytes(10, 2));
  EXPECT_EQ(state.avatars.at(2).package_serial, 2u);
}

TEST(RoomState, ArrivalsDeparturesAndChatAreRecorded) {
  RoomState state;
  state.avatar_joined(avatar_info(5, "eve"));
  EXPECT_EQ(state.chat_line({5, "hello"}), "eve");
  EXPECT_EQ(state.chat_line({6, "who?"}), "avatar 6") << "a writer the client does not know";
  EXPECT_EQ(state.avatar_left(5), "eve");
  EXPECT_TRUE(state.avatars.empty());
  ASSERT_EQ(state.events.size(), 4u);
  EXPECT_EQ(state.events[0].kind, "joined");
  EXPECT_EQ(state.events[1].text, "hello");
  EXPECT_EQ(state.events[3].kind, "left");
}

TEST(RoomState, ALineBegunIsRecordedWithItsLanguageLengthAndTime) {
  RoomState state;
  const auto now = Clock::now();
  state.welcomed(welcome_of(1, {avatar_info(1, "me"), avatar_info(5, "Anna")}), {}, now);
  state.stats.joined(now);
  const auto line = state.line_begun({5, 301, 4650, "de", "Im Jahr 1999"}, now + std::chrono::milliseconds(12340));
  ASSERT_TRUE(line);
  EXPECT_EQ(*line, "[12.3 s] Anna says (de, 4650 ms): Im Jahr 1999");
  ASSERT_FALSE(state.events.empty());
  const RoomEventRecord& event = state.events.back();
  EXPECT_EQ(event.kind, "speaking");
  EXPECT_EQ(event.name, "Anna");
  EXPECT_EQ(event.text, "Im Jahr 1999");
  EXPECT_EQ(event.language, "de");
  EXPECT_EQ(event.duration_ms, 4650u);
  EXPECT_EQ(event.tick, 301u);
  state.mutes = MuteList({"Anna"});
  const std::size_t events = state.events.size();
  EXPECT_FALSE(state.line_begun({5, 400, 1000, "de", "noch einmal"}, now)) << "muted: nothing to show";
  EXPECT_EQ(state.events.size(), events);
}

TEST(RoomState, KeepsTheLastEventsOnly) {
  RoomState state;
  for (std::size_t i = 0; i < RoomState::kMaxEvents + 10; ++i) state.chat_line({1, "line " + std::to_string(i)});
  EXPECT_EQ(state.events.size(), RoomState::kMaxEvents);
  EXPECT_EQ(state.events.front().text, "line 10");
}

TEST(RoomState, FacesAreTheDecodedOnesInSeatOrderExtrapolatedToNow) {
  RoomState state;
  state.welcomed(welcome_of(1, {avatar_info(1, "ada"), avatar_info(2, "bob"), avatar_info(3, "cyd")}), {}, Clock::now());
  state.stream_started(codec::StreamOptions{});
  FaceStream cyd, ada;
  const auto at = Clock::now();
  EXPECT_TRUE(state.decode_room_frame(room_frame({{3, cyd.frame(face(0.7f))}, {1, ada.frame(face(0.2f))}}), at));
  const auto faces = state.faces(at);
  ASSERT_EQ(faces.size(), 2u) << "bob sent no frame";
  EXPECT_EQ(faces[0].avatar, 1u);
  EXPECT_EQ(faces[1].avatar, 3u);
  EXPECT_EQ(codec::quantise(faces[1].params), cyd.reconstruction());
  EXPECT_EQ(state.stats.frames_of(3), 1u);
  EXPECT_EQ(state.avatars.at(3).last_frame_at, at);
}

TEST(RoomState, TheSceneHasSeatsAttentionFacesAndTheLastChatLine) {
  RoomState state;
  EXPECT_EQ(state.scene(Clock::now(), "me").you, 0u) << "before the welcome";
  EXPECT_EQ(state.scene(Clock::now(), "me").your_name, "me");
  codec::AvatarInfo ada = avatar_info(1, "ada"), bob = avatar_info(2, "bob");
  ada.seat = {-210.0f, 0.0f, 47.0f, 0.44f};
  state.welcomed(welcome_of(2, {ada, bob}), {}, Clock::now());
  state.stream_started(codec::StreamOptions{});
  FaceStream ada_face;
  const auto at = Clock::now();
  ASSERT_TRUE(state.decode_room_frame(room_frame({{1, ada_face.frame(face(0.5f))}}), at));
  state.attention_changed({{{1, codec::AttentionTarget::avatar, 2}}});
  state.chat_line({1, "first"});
  state.chat_line({2, "second"});
  const RoomScene scene = state.scene(at, "me");
  EXPECT_EQ(scene.you, 2u);
  EXPECT_EQ(scene.your_name, "bob") << "the room's name for the viewer, once there";
  ASSERT_EQ(scene.members.size(), 2u);
  EXPECT_EQ(scene.members[0].seat, ada.seat);
  ASSERT_TRUE(scene.members[0].face.has_value());
  EXPECT_EQ(scene.members[0].attention.target, codec::AttentionTarget::avatar);
  EXPECT_EQ(scene.members[0].attention.target_avatar, 2u);
  EXPECT_FALSE(scene.members[1].face.has_value()) << "bob sent no frame";
  EXPECT_EQ(scene.members[1].attention.target, codec::AttentionTarget::room) << "the room until told";
  EXPECT_EQ(scene.caption, "bob: second");
}

TEST(RoomState, UndecodableFramesAreCounted) {
  RoomState state;
  state.stream_started(codec::StreamOptions{});
  EXPECT_FALSE(state.decode_room_frame(Bytes{0x23, 0xff}, Clock::now()));
  FaceStream bob;
  bob.frame(face(0.1f));
  EXPECT_FALSE(state.decode_room_frame(room_frame({{2, bob.frame(face(0.9f))}}), Clock::now()))
      << "a predicted frame before its key frame";
  EXPECT_EQ(state.stats.summary(Clock::now())["decode_errors"], 2);
  EXPECT_EQ(state.decoder.needing_key_frames(), (std::vector<std::uint32_t>{2}));
}

TEST(RoomState, ANewConnectionStartsAFreshStreamOutOfTheRoom) {
  RoomState state;
  state.welcomed(welcome_of(1, {avatar_info(2, "bob")}), {}, Clock::now());
  state.stream_started(codec::StreamOptions{});
  FaceStream bob;
  state.decode_room_frame(room_frame({{2, bob.frame(face(0.5f))}}), Clock::now());
  state.connection_started();
  EXPECT_FALSE(state.joined);
  EXPECT_EQ(state.decoder.size(), 0u);
  EXPECT_EQ(state.avatars.size(), 1u) << "the avatars stay until the next welcome";
}

}  // namespace
}  // namespace fw::client
