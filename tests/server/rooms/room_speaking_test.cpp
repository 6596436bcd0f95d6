// Speaking (PROTOCOL.md 5.15) through the server core: a person's language
// from their hello, the line said in it with the track the speech worker
// made, and the speaking message to version-4 sessions before the frame
// that carries the line; none to version-3 sessions, which keep working.
#include <string>

#include <gtest/gtest.h>

#include "espeak_length.hpp"
#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using test::espeak_track_ms;
using codec::CloseCode;
using test::HelloOptions;
using test::InMemoryServer;

constexpr const char* kLine = test::kLineLongerInGerman;

TEST(RoomSpeaking, AnUnknownLanguageIsRefusedSayingWhereTheListIs) {
  InMemoryServer server;
  auto peer = server.join("r", "Ann", HelloOptions{.language = "xx"});
  ASSERT_TRUE(peer->closing);
  EXPECT_EQ(peer->closing->code, CloseCode::bad_request);
  EXPECT_EQ(peer->closing->reason, "unknown language 'xx'; GET /api/languages lists the ones this server speaks");
  EXPECT_FALSE(peer->welcome);
  // A language of another shape is no hello of the protocol at all. The
  // codec will not write one, so its bytes are made by hand: a hello in "de"
  // whose last field, the language, is then shouted.
  codec::Hello hello;
  hello.room = "r";
  hello.name = "Bo";
  hello.language = "de";
  std::vector<std::uint8_t> bytes;
  codec::write_message(hello, bytes);
  bytes[bytes.size() - 2] = 'D';
  bytes[bytes.size() - 1] = 'E';
  auto shouting = server.connect();
  shouting->send_bytes(std::move(bytes));
  shouting->read_until([&] { return shouting->closing.has_value(); });
  ASSERT_TRUE(shouting->closing);
  EXPECT_EQ(shouting->closing->code, CloseCode::protocol_error);
}

TEST(RoomSpeaking, AVersion4SessionIsToldBeforeTheLinesFrameAndAVersion3OneIsNot) {
  InMemoryServer server;
  auto anna = server.join("r", "Anna", HelloOptions{.timestamps = true, .language = "de"});
  auto bob = server.join("r", "Bob", HelloOptions{.timestamps = true, .version = 3});
  ASSERT_TRUE(anna->welcome && bob->welcome);
  EXPECT_EQ(anna->welcome->protocol_version, codec::kProtocolVersion);
  EXPECT_EQ(bob->welcome->protocol_version, 3) << "a version-3 client is answered in its version";
  anna->send(codec::Chat{0, kLine});
  ASSERT_TRUE(anna->read_until([&] { return !anna->speaking.empty(); }));
  const codec::Speaking& said = anna->speaking.front();
  EXPECT_EQ(said.avatar, anna->welcome->you);
  EXPECT_EQ(said.language, "de");
  EXPECT_EQ(said.text, kLine);
  EXPECT_NEAR(said.duration_ms, espeak_track_ms(kLine, "de"), 30.0) << "the German track's own length";
  EXPECT_LT(anna->last_tick_before_speaking.front(), said.tick) << "no frame of the line came before it";
  // The frames go on past the line's first.
  ASSERT_TRUE(anna->read_until([&] { return !anna->ticks.empty() && anna->ticks.back().second >= said.tick; }));
  // Bob sees the line and the faces, and no message he could not read.
  ASSERT_TRUE(bob->read_until([&] { return !bob->chat.empty() && !bob->ticks.empty() && bob->ticks.back().second >= said.tick; }));
  EXPECT_TRUE(bob->speaking.empty());
  EXPECT_TRUE(bob->errors.empty()) << bob->errors.front();
  EXPECT_TRUE(anna->errors.empty()) << anna->errors.front();
  // Bob's lines are said in the server's default language.
  bob->send(codec::Chat{0, "see you"});
  ASSERT_TRUE(anna->read_until([&] { return anna->speaking.size() == 2; }));
  EXPECT_EQ(anna->speaking.back().language, "en");
  EXPECT_EQ(anna->speaking.back().avatar, bob->welcome->you);
}

}  // namespace
}  // namespace fw::server
