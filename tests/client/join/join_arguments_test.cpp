#include "join_arguments.hpp"

#include <gtest/gtest.h>

namespace fw::client {
namespace {

JoinArgs valid_args() {
  JoinArgs args;
  args.url = "ws://127.0.0.1:8080/";
  args.room = "lobby";
  args.name = "Ada L.";
  return args;
}

std::string plan_error(const JoinArgs& args) {
  JoinPlan plan;
  std::string error;
  EXPECT_FALSE(plan_join(args, plan, error));
  return error;
}

TEST(JoinArguments, APlanHasTheServerAndTheFrameSize) {
  JoinArgs args = valid_args();
  args.size = "320x180";
  args.samples = 4;
  JoinPlan plan;
  std::string error;
  ASSERT_TRUE(plan_join(args, plan, error)) << error;
  ASSERT_EQ(plan.servers.size(), 1u);
  EXPECT_EQ(plan.servers[0].host, "127.0.0.1");
  EXPECT_EQ(plan.servers[0].port, "8080");
  EXPECT_EQ(plan.render.width, 320);
  EXPECT_EQ(plan.render.height, 180);
  EXPECT_EQ(plan.render.samples, 4);
}

TEST(JoinArguments, SeveralServersAreTakenInTheirOrder) {
  JoinArgs args = valid_args();
  args.url = "ws://127.0.0.1:1/,tcp://127.0.0.1:8081";
  JoinPlan plan;
  std::string error;
  ASSERT_TRUE(plan_join(args, plan, error)) << error;
  ASSERT_EQ(plan.servers.size(), 2u);
  EXPECT_EQ(plan.servers[0].port, "1");
  EXPECT_EQ(plan.servers[1].scheme, ServerUrl::Scheme::tcp);
  args.url = "ws://127.0.0.1:1/,ws://127.0.0.1:0/";
  EXPECT_EQ(plan_error(args).rfind("server 2 of 2: ", 0), 0u);
}

TEST(JoinArguments, SaysWhichFlagIsWrong) {
  JoinArgs args = valid_args();
  args.url = "http://example.org";
  EXPECT_NE(plan_error(args).find("only ws:// and tcp://"), std::string::npos);
  args = valid_args();
  args.room = "no spaces";
  EXPECT_EQ(plan_error(args).rfind("--room must be 1..64 characters", 0), 0u);
  args = valid_args();
  args.name = "tab\there";
  EXPECT_EQ(plan_error(args).rfind("--name must be", 0), 0u);
  args = valid_args();
  args.say = {"fine", ""};
  EXPECT_EQ(plan_error(args).rfind("--say: a chat line holds 1..500 bytes", 0), 0u);
  args = valid_args();
  args.mute = {"Bob", std::string(33, 'b')};
  EXPECT_EQ(plan_error(args).rfind("--mute takes a display name as others see it: 1..32 bytes", 0), 0u);
  args = valid_args();
  args.token = std::string(513, 't');
  EXPECT_EQ(plan_error(args).rfind("--token", 0), 0u);
  args = valid_args();
  args.size = "640x";
  EXPECT_EQ(plan_error(args).rfind("--size must look like 640x360", 0), 0u);
  args.size = "8x8";
  EXPECT_EQ(plan_error(args), "--size: width and height must each be 16..4096 pixels");
}

TEST(JoinArguments, ALanguageIsCheckedForShapeAndGoesIntoTheHello) {
  JoinArgs args = valid_args();
  for (const char* bad : {"DE", "en_US", "english please", "abcdefghijklmnopq"}) {
    args.language = bad;
    const std::string error = plan_error(args);
    EXPECT_EQ(error.rfind("--language takes a language as espeak-ng names it", 0), 0u) << error;
    EXPECT_NE(error.find(std::string("not '") + bad + "'"), std::string::npos) << error;
    EXPECT_NE(error.find("GET /api/languages"), std::string::npos) << error;
  }
  // Whether the server speaks it is the server's to say (closing 10).
  for (const char* fine : {"", "de", "pt-br", "xx"}) {
    args.language = fine;
    JoinPlan plan;
    std::string error;
    EXPECT_TRUE(plan_join(args, plan, error)) << fine << ": " << error;
    EXPECT_EQ(session_options(args, "", "", nullptr).language, fine);
  }
}

TEST(JoinArguments, AFrameSizeIsTwoWholeNumbersAroundAnX) {
  int width = 0, height = 0;
  EXPECT_TRUE(parse_frame_size("640x360", width, height));
  EXPECT_EQ(width, 640);
  EXPECT_EQ(height, 360);
  for (const char* bad : {"640", "x360", "640x360px", "6.4x3", "640X360", "axb", ""})
    EXPECT_FALSE(parse_frame_size(bad, width, height)) << bad;
  EXPECT_EQ(width, 640) << "untouched on failure";
}

TEST(JoinArguments, TimestampsAreLeftOffOnSlowLinksUnlessAskedFor) {
  JoinArgs args = valid_args();
  EXPECT_TRUE(wants_timestamps(args)) << "the server's default budget";
  args.max_kbps = 9.6;
  EXPECT_FALSE(wants_timestamps(args));
  args.timestamps = "on";
  EXPECT_TRUE(wants_timestamps(args));
  args.max_kbps = 64;
  args.timestamps = "off";
  EXPECT_FALSE(wants_timestamps(args));
  args.timestamps = "auto";
  EXPECT_TRUE(wants_timestamps(args));
}

TEST(JoinArguments, TheSessionGetsTheRoomTheFaceAndTheBudget) {
  JoinArgs args = valid_args();
  args.max_kbps = 9.6;
  args.token = "fw1.x";
  args.say = {"hi"};
  args.emote = "joy";
  const auto own = std::make_shared<const std::vector<std::uint8_t>>(std::vector<std::uint8_t>{1});
  const SessionOptions options = session_options(args, "asset7", "key7", own);
  EXPECT_EQ(options.room, "lobby");
  EXPECT_EQ(options.name, "Ada L.");
  EXPECT_EQ(options.avatar_asset, "asset7");
  EXPECT_EQ(options.avatar_key, "key7");
  EXPECT_EQ(options.own_package, own);
  EXPECT_EQ(options.token, "fw1.x");
  EXPECT_EQ(options.max_bps, 9600u);
  EXPECT_FALSE(options.timestamps);
  EXPECT_EQ(options.say, std::vector<std::string>{"hi"});
  EXPECT_EQ(options.emote, "joy");
}

}  // namespace
}  // namespace fw::client
