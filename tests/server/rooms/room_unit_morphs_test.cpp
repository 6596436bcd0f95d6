// Unit morphs (PROTOCOL.md 5.17) through the server core: a person's AU
// definition reaches everyone of version 5 in the room, and whoever joins
// later; a version-4 session is never sent one; a restore is a new version.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using test::HelloOptions;
using test::InMemoryServer;

codec::Command script(std::uint32_t request, std::string text) {
  codec::Command command;
  command.request_id = request;
  command.kind = codec::Command::Kind::facs;
  command.sentence = std::move(text);
  return command;
}

TEST(RoomUnitMorphs, ADefinitionReachesEveryoneAndLaterJoinersAndARestoreIsANewVersion) {
  InMemoryServer server;
  auto anna = server.join("r", "Anna");
  auto bob = server.join("r", "Bob");
  auto old = server.join("r", "Old", HelloOptions{.version = 4});
  ASSERT_TRUE(anna->welcome && bob->welcome && old->welcome);
  const std::uint32_t id = anna->welcome->you;
  anna->send(script(1, "AU 9 nose 0 0 3 0 end"));
  ASSERT_TRUE(bob->read_until([&] { return !bob->unit_morphs.empty(); }));
  const codec::UnitMorphs& sent = bob->unit_morphs.front();
  EXPECT_EQ(sent.avatar, id);
  EXPECT_EQ(sent.version, 1u);
  ASSERT_EQ(sent.units.size(), 1u);
  EXPECT_EQ(sent.units[0].channel, codec::au_channel(9, codec::AuSide::both));
  EXPECT_FALSE(sent.units[0].moves.empty());
  ASSERT_TRUE(anna->read_until([&] { return !anna->results.empty() && !anna->unit_morphs.empty(); }));
  EXPECT_EQ(anna->results.front().error, "");
  EXPECT_EQ(anna->unit_morphs.front().units, sent.units);
  // A later joiner is told after its welcome.
  auto carl = server.join("r", "Carl");
  ASSERT_TRUE(carl->read_until([&] { return !carl->unit_morphs.empty(); }));
  EXPECT_EQ(carl->unit_morphs.front().units, sent.units);
  EXPECT_EQ(carl->unit_morphs.front().version, 1u);
  // A restore goes to everyone as a new version with no units.
  anna->send(script(2, "AU 9 end"));
  ASSERT_TRUE(carl->read_until([&] { return carl->unit_morphs.size() == 2; }));
  EXPECT_EQ(carl->unit_morphs.back().version, 2u);
  EXPECT_TRUE(carl->unit_morphs.back().units.empty());
  // A refused definition sends nothing and says why.
  anna->send(script(3, "AU 9 nose 0 0 300 0 end"));
  ASSERT_TRUE(anna->read_until([&] { return anna->results.size() == 3; }));
  EXPECT_NE(anna->results.back().error.find("at most 40 along each axis"), std::string::npos) << anna->results.back().error;
  old->read_for(std::chrono::milliseconds(300));
  carl->read_for(std::chrono::milliseconds(300));
  EXPECT_TRUE(old->unit_morphs.empty()) << "a version-4 session never gets one";
  EXPECT_TRUE(old->errors.empty());
  EXPECT_EQ(carl->unit_morphs.size(), 2u);
}

}  // namespace
}  // namespace fw::server
