// Muting for oneself (`join --mute NAME`), without sockets: the lines of a
// muted name are neither recorded nor shown but counted, its faces are
// drawn at rest and re-aimed at nobody, everyone wearing the name is muted
// and the viewer never, and what the person reads on joining says so.
#include "mute_list.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "room_state.hpp"
#include "room_summary.hpp"
#include "server_messages.hpp"
#include "view_plan.hpp"

namespace fw::client {
namespace {

using namespace fw::client::test;
using Clock = std::chrono::steady_clock;

codec::Welcome welcome_of(std::uint32_t you, std::vector<codec::AvatarInfo> avatars) {
  codec::Welcome welcome;
  welcome.you = you;
  welcome.room = "lobby";
  welcome.tick_hz = 30;
  welcome.avatars = std::move(avatars);
  return welcome;
}

// A room of four, seated on an arc: the viewer ada (1), two people named
// bob (2 and 4), and cyd (3).
codec::Welcome four_people() {
  std::vector<codec::AvatarInfo> people{avatar_info(1, "ada"), avatar_info(2, "bob"), avatar_info(3, "cyd"),
                                        avatar_info(4, "bob")};
  for (std::size_t i = 0; i < people.size(); ++i) {
    const float phi = (static_cast<float>(i) - 1.5f) * 0.6f;
    people[i].seat = {1000.0f * std::sin(phi), 0.0f, 1000.0f - 1000.0f * std::cos(phi), -phi};
  }
  return welcome_of(1, people);
}

TEST(MuteList, MutesEveryoneOfTheNameButNeverTheViewer) {
  const MuteList mutes({"bob"});
  EXPECT_TRUE(mutes.mutes(2, "bob", 1));
  EXPECT_TRUE(mutes.mutes(4, "bob", 1));
  EXPECT_FALSE(mutes.mutes(3, "cyd", 1));
  EXPECT_FALSE(mutes.mutes(1, "bob", 1)) << "the viewer's own avatar, whatever its name";
  EXPECT_FALSE(mutes.mutes(0, "bob", 1)) << "the server's lines (avatar 0)";
  EXPECT_FALSE(MuteList().mutes(2, "bob", 1));
}

TEST(MuteList, TheNoticesSayWhomANameMutesHere) {
  const MuteList mutes({"bob", "cyd", "dan"});
  const std::vector<std::string> notices = mutes.notices(four_people().avatars, 1);
  ASSERT_EQ(notices.size(), 3u);
  EXPECT_NE(notices[0].find("muted bob for you alone"), std::string::npos) << notices[0];
  EXPECT_NE(notices[0].find("2 people here share that name, all of them are muted"), std::string::npos) << notices[0];
  EXPECT_NE(notices[1].find("muted cyd"), std::string::npos) << notices[1];
  EXPECT_EQ(notices[1].find("share"), std::string::npos) << notices[1];
  EXPECT_NE(notices[2].find("nobody of that name is here yet"), std::string::npos) << notices[2];
}

TEST(MuteList, AMutedNamesLinesAreCountedNotRecorded) {
  RoomState state;
  state.mutes = MuteList({"bob"});
  state.welcomed(four_people(), {}, Clock::now());
  EXPECT_TRUE(state.muted(2));
  EXPECT_TRUE(state.muted(4));
  EXPECT_FALSE(state.muted(3));
  EXPECT_FALSE(state.muted(1));
  EXPECT_EQ(state.chat_line({2, "hello"}), "bob");
  state.chat_line({3, "hi bob"});
  state.chat_line({4, "the other bob"});
  state.chat_line({1, "me"});
  ASSERT_EQ(state.events.size(), 2u);
  EXPECT_EQ(state.events[0].text, "hi bob");
  EXPECT_EQ(state.events[1].text, "me");
  EXPECT_EQ(state.mutes.hidden_lines().at("bob"), 2);
  EXPECT_EQ(state.scene(Clock::now(), "ada").caption, "ada: me");
  state.chat_line({2, "last word"});
  EXPECT_EQ(state.scene(Clock::now(), "ada").caption, "ada: me") << "a muted line never becomes the caption";

  const nlohmann::json summary = room_summary(state, Clock::now());
  EXPECT_EQ(summary.at("muted").at("names"), nlohmann::json::array({"bob"}));
  EXPECT_EQ(summary.at("muted").at("avatars_in_room"), 2);
  EXPECT_EQ(summary.at("muted").at("lines_hidden").at("bob"), 3);
  EXPECT_FALSE(room_summary(RoomState(), Clock::now()).contains("muted")) << "nothing said when nobody is muted";
}

TEST(MuteList, AMutedFaceIsDrawnAtRestAndReAimedAtNobody) {
  RoomState state;
  state.mutes = MuteList({"bob"});
  state.welcomed(four_people(), {}, Clock::now());
  state.stream_started(codec::StreamOptions{});
  FaceStream bob, cyd;
  codec::FaceParams blushing = face(0.9f);
  blushing.blush = {0.8f, 0.8f, 0.0f, 0.0f, 0.0f};
  blushing.eye_left = blushing.eye_right = {0.2f, 0.1f};
  blushing.lid_left = blushing.lid_right = 0.5f;
  const auto at = Clock::now();
  ASSERT_TRUE(state.decode_room_frame(room_frame({{2, bob.frame(blushing)}, {3, cyd.frame(blushing)}}), at));
  // Both look at the viewer: the unmuted face is re-aimed at the camera, the muted one is not.
  state.attention_changed({{{2, codec::AttentionTarget::avatar, 1}, {3, codec::AttentionTarget::avatar, 1}}});
  const RoomScene scene = state.scene(at, "ada");
  const SceneMember& muted = scene.members[1];
  ASSERT_EQ(muted.id, 2u);
  EXPECT_TRUE(muted.still);
  EXPECT_EQ(muted.name, "bob (muted)") << "marked under the face";
  ASSERT_TRUE(muted.face.has_value());
  EXPECT_EQ(codec::quantise(*muted.face), codec::quantise(codec::FaceParams{}));
  EXPECT_FALSE(scene.members[3].face.has_value()) << "the other bob sent no frame: not drawn yet";
  EXPECT_FALSE(scene.members[2].still);
  EXPECT_GT(scene.members[2].face->au_intensity(12), 0.5f) << "cyd smiles on";

  std::map<std::uint32_t, GazeBlend> blends;
  ViewPlan plan = plan_view(scene, 640, 360, blends);
  const auto later = at + std::chrono::seconds(1);  // past any blend
  RoomScene again = state.scene(later, "ada");
  plan = plan_view(again, 640, 360, blends);
  ASSERT_EQ(plan.others.size(), 2u);
  for (const PlacedFace& placed : plan.others) {
    if (placed.id == 2) {
      EXPECT_EQ(codec::quantise(placed.params), codec::quantise(codec::FaceParams{})) << "straight ahead, at rest";
    } else {
      EXPECT_NE(placed.params.head_yaw_rad + placed.params.eye_left.yaw_rad, blushing.head_yaw_rad + blushing.eye_left.yaw_rad)
          << "the unmuted face is re-aimed at the viewer";
    }
  }
  EXPECT_EQ(blends.count(2), 0u) << "a still face keeps no blend";
}

TEST(MuteList, ArrivalsOfAMutedNameAreMutedToo) {
  RoomState state;
  state.mutes = MuteList({"eve"});
  state.welcomed(four_people(), {}, Clock::now());
  state.avatar_joined(avatar_info(7, "eve"));
  EXPECT_TRUE(state.muted(7));
  state.chat_line({7, "hi all"});
  EXPECT_EQ(state.events.back().kind, "joined") << "the arrival is recorded, the line is not";
  state.avatar_left(7);
  state.avatar_joined(avatar_info(8, "eve"));
  EXPECT_TRUE(state.muted(8)) << "back under another avatar id: still muted";
}

}  // namespace
}  // namespace fw::client
