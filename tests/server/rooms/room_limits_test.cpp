// What keeps one client from taking a room, through in-memory connections
// (each with the peer address a test gives it): avatar ids handed out again
// after a quiet period, so a lobby's ids never run out; persons who neither
// send nor read let go, and a room left without persons closed; joins, new
// rooms, seats and chat lines limited per address and per room.
// tests/server/net/address_rate_limits_test.cpp does the same over sockets.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "avatar_ids.hpp"
#include "in_memory_server.hpp"
#include "room_registry.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::eventually;
using test::InMemoryPeer;
using test::InMemoryServer;
using namespace std::chrono_literals;

// --- avatar ids ----------------------------------------------------------------

TEST(AvatarIds, AnIdRestsForItsQuietPeriodBeforeItIsHandedOutAgain) {
  AvatarIds ids(/*space=*/4, /*quiet_ticks=*/10);  // ids 1, 2, 3
  EXPECT_EQ(ids.take(0), 1u);
  EXPECT_EQ(ids.take(0), 2u);
  EXPECT_EQ(ids.take(0), 3u);
  EXPECT_EQ(ids.take(0), 0u) << "all in use";
  ids.give_back(2, 5);
  EXPECT_EQ(ids.take(14), 0u) << "2 rests until tick 15";
  EXPECT_EQ(ids.take(15), 2u);
}

TEST(AvatarIds, IdsGoRoundSoThatAnIdComesBackAsLateAsPossible) {
  AvatarIds ids(/*space=*/6, /*quiet_ticks=*/0);
  const auto first = ids.take(0);  // 1
  ids.give_back(first, 0);
  EXPECT_EQ(ids.take(0), 2u) << "not 1 again at once";
  EXPECT_EQ(ids.take(0), 3u);
  EXPECT_EQ(ids.take(0), 4u);
  EXPECT_EQ(ids.take(0), 5u);
  EXPECT_EQ(ids.take(0), 1u) << "round again";
}

/// A peer that said hello from `from` and got its welcome or closing message.
std::unique_ptr<InMemoryPeer> join_from(InMemoryServer& server, const std::string& from, const std::string& room,
                                        const std::string& name) {
  auto peer = server.connect(from);
  peer->hello(room, name);
  peer->read_until([&] { return peer->welcome.has_value() || peer->closing.has_value(); });
  return peer;
}

ServerConfig lobby_with_ids(std::uint32_t space, std::chrono::milliseconds quiet) {
  ServerConfig config = InMemoryServer::test_config(3);
  config.demo_room = true;
  config.avatar_id_space = space;
  config.avatar_id_quiet = quiet;
  return config;
}

// A join storm as long as the codec's 2^21 ids last at 5,800 joins a
// second, shrunk to 64 ids: the lobby still admits, within its id space,
// and its frames decode.
TEST(RoomLimits, ALobbyThroughManyJoinsAndLeavesKeepsAdmittingWithinItsIds) {
  constexpr std::uint32_t kSpace = 64;
  InMemoryServer server(lobby_with_ids(kSpace, 200ms));
  ASSERT_TRUE(eventually([&] { return server.core().state().ready.load(); }));
  int admitted = 0;
  for (int attempt = 0; attempt < 3000 && admitted < 300; ++attempt) {
    auto peer = server.join("lobby", "Cycler");
    if (peer->welcome) {
      ++admitted;
      EXPECT_LT(peer->welcome->you, kSpace);
      EXPECT_NE(peer->welcome->you, 0u);
    } else {
      ASSERT_TRUE(peer->closing);
      EXPECT_EQ(peer->closing->code, CloseCode::server_full) << peer->closing->reason;
      std::this_thread::sleep_for(50ms);  // every id rests: give them time
    }
  }
  EXPECT_EQ(admitted, 300) << "ids come back after 0.2 s";

  // The storm may have left every id resting: one is free within 0.2 s.
  auto viewer = server.join("lobby", "Viewer");
  for (int i = 0; i < 20 && !viewer->welcome; ++i) {
    std::this_thread::sleep_for(100ms);
    viewer = server.join("lobby", "Viewer");
  }
  ASSERT_TRUE(viewer->welcome) << (viewer->closing ? viewer->closing->reason : "no answer");
  EXPECT_LT(viewer->welcome->you, kSpace);
  ASSERT_EQ(viewer->welcome->avatars.size(), 4u);
  EXPECT_TRUE(viewer->read_until([&] { return viewer->frames_per_avatar.size() >= 3; }, 10s))
      << viewer->frames_per_avatar.size() << " faces streamed, " << viewer->package_order.size() << " packages, "
      << viewer->room_frames << " frames, " << viewer->bytes_received << " bytes, " << viewer->attention.size()
      << " attention";
  EXPECT_TRUE(viewer->errors.empty()) << viewer->errors.front();
}

TEST(RoomLimits, WhenEveryIdRestsAJoinIsRefusedUntilOneIsFreeAgain) {
  // Ids 1 .. 15: the lobby's three avatars hold 1 .. 3, twelve are left.
  InMemoryServer server(lobby_with_ids(16, 3s));
  ASSERT_TRUE(eventually([&] { return server.core().state().ready.load(); }));
  for (int i = 0; i < 12; ++i) {
    auto peer = server.join("lobby", "Cycler");
    ASSERT_TRUE(peer->welcome) << i << ": " << (peer->closing ? peer->closing->reason : "no answer");
  }
  auto refused = server.join("lobby", "Cycler");
  ASSERT_TRUE(refused->closing);
  EXPECT_EQ(refused->closing->code, CloseCode::server_full);
  EXPECT_NE(refused->closing->reason.find("avatar ids"), std::string::npos) << refused->closing->reason;

  // The ids rest 3 s of the room's ticks: on a loaded machine the room may
  // tick late, so the test asks again until then, not at a fixed moment.
  std::this_thread::sleep_for(2500ms);
  std::unique_ptr<InMemoryPeer> later;
  for (int attempt = 0; attempt < 40 && !(later && later->welcome); ++attempt) {
    if (attempt > 0) std::this_thread::sleep_for(250ms);
    later = server.join("lobby", "Cycler");
  }
  ASSERT_TRUE(later->welcome) << (later->closing ? later->closing->reason : "no answer");
  EXPECT_EQ(later->welcome->you, 4u) << "the id that rested longest";
}

// --- squatting -------------------------------------------------------------------

ServerConfig idle_config() {
  ServerConfig config = InMemoryServer::test_config();
  config.timeouts.idle_person = 1s;
  config.timeouts.close = 300ms;
  return config;
}

/// Both keep pinging (a ping keeps a connection, not a seat) for `duration`;
/// the viewer reads.
void ping_for(InMemoryPeer& viewer, InMemoryPeer& squatter, std::chrono::milliseconds duration) {
  const auto end = std::chrono::steady_clock::now() + duration;
  for (std::uint32_t n = 0; std::chrono::steady_clock::now() < end; ++n) {
    viewer.send(codec::Ping{n, 0});
    squatter.send(codec::Ping{n, 0});
    viewer.read_for(200ms);
  }
}

TEST(RoomLimits, APersonWhoNeitherSendsNorReadsIsLetGoAndAQuietViewerStays) {
  InMemoryServer server(idle_config());
  auto viewer = server.join("quiet", "Viewer");
  auto squatter = server.join("quiet", "Squatter");
  ASSERT_TRUE(viewer->welcome && squatter->welcome);
  squatter->session().set_reading(false);
  ping_for(*viewer, *squatter, 4s);
  ASSERT_TRUE(eventually([&] { return squatter->session().gone(); }, 2s)) << "the squatter is let go";
  EXPECT_EQ(squatter->session().shut_down(), CloseCode::idle_timeout);
  EXPECT_EQ(server.core().abuse().count(Abuse::idle_person), 1u);
  EXPECT_FALSE(viewer->session().gone()) << "who reads stays, though it only pings";
  EXPECT_TRUE(viewer->read_until([&] { return viewer->presence.size() >= 2; }));
  EXPECT_EQ(viewer->presence.back().change, codec::Presence::Change::left);
}

TEST(RoomLimits, ARoomWhoseOnlyPersonIsLetGoCloses) {
  InMemoryServer server(idle_config());
  auto squatter = server.join("squat", "Squatter");
  ASSERT_TRUE(squatter->welcome);
  squatter->session().set_reading(false);
  const auto has_room = [&] {
    for (const auto& room : server.core().rooms().list())
      if (room.name == "squat") return true;
    return false;
  };
  EXPECT_TRUE(has_room());
  EXPECT_TRUE(eventually([&] { return squatter->session().gone(); }, 5s));
  EXPECT_TRUE(eventually([&] { return !has_room(); }, 3s));
}

TEST(RoomLimits, ARoomMadeForARefusedJoinDoesNotStay) {
  ServerConfig config = InMemoryServer::test_config();
  config.room_size = 2;
  config.abuse.seats_per_address = 0;  // one seat per address
  InMemoryServer server(config);
  auto first = join_from(server, "10.0.0.1", "pair", "First");
  ASSERT_TRUE(first->welcome);
  auto second = join_from(server, "10.0.0.1", "pair", "Second");
  ASSERT_TRUE(second->closing);
  first.reset();
  second.reset();
  EXPECT_TRUE(eventually([&] { return server.core().rooms().list().empty(); }, 3s));
}

TEST(RoomLimits, OneAddressHoldsAtMostHalfOfARoomsSeats) {
  ServerConfig config = InMemoryServer::test_config();
  config.room_size = 4;
  config.abuse.seats_per_address = 0;  // half the room: 2
  InMemoryServer server(config);
  auto a1 = join_from(server, "10.0.0.1", "r", "A1");
  auto a2 = join_from(server, "10.0.0.1", "r", "A2");
  auto a3 = join_from(server, "10.0.0.1", "r", "A3");
  auto b1 = join_from(server, "10.0.0.2", "r", "B1");
  ASSERT_TRUE(a1->welcome && a2->welcome);
  ASSERT_TRUE(a3->closing);
  EXPECT_EQ(a3->closing->code, CloseCode::room_full);
  EXPECT_NE(a3->closing->reason.find("from your address"), std::string::npos) << a3->closing->reason;
  EXPECT_TRUE(b1->welcome) << "another address still joins";
  EXPECT_EQ(server.core().abuse().count(Abuse::room_seats), 1u);
}

TEST(RoomLimits, OneNetworksAddressesTogetherHoldAtMostThreeQuartersOfARoomsSeats) {
  ServerConfig config = InMemoryServer::test_config();
  config.room_size = 8;
  config.abuse.seats_per_address = 0;  // half the room: 4 per address
  config.abuse.seats_per_block = 0;    // three quarters: 6 per /24
  InMemoryServer server(config);
  std::vector<std::unique_ptr<InMemoryPeer>> seated;
  for (int i = 1; i <= 6; ++i) {
    seated.push_back(join_from(server, "10.0.0." + std::to_string(i), "r", "Neighbour"));
    ASSERT_TRUE(seated.back()->welcome) << i;
  }
  auto seventh = join_from(server, "10.0.0.7", "r", "Neighbour");
  ASSERT_TRUE(seventh->closing);
  EXPECT_EQ(seventh->closing->code, CloseCode::room_full);
  EXPECT_NE(seventh->closing->reason.find("from your network"), std::string::npos) << seventh->closing->reason;
  EXPECT_TRUE(join_from(server, "10.0.1.1", "r", "Elsewhere")->welcome) << "another /24 still joins";
}

TEST(RoomLimits, OneAddressCreatesAtMostFiveRoomsAtOnce) {
  ServerConfig config = InMemoryServer::test_config();
  config.abuse.room_creations = AbuseLimits{}.room_creations;
  InMemoryServer server(config);
  std::vector<std::unique_ptr<InMemoryPeer>> held;
  for (int i = 1; i <= 5; ++i) {
    held.push_back(join_from(server, "10.0.0.1", "room" + std::to_string(i), "Squatter"));
    ASSERT_TRUE(held.back()->welcome) << i;
  }
  auto sixth = join_from(server, "10.0.0.1", "room6", "Squatter");
  ASSERT_TRUE(sixth->closing);
  EXPECT_EQ(sixth->closing->code, CloseCode::rate_limited);
  EXPECT_NE(sixth->closing->reason.find("too many new rooms"), std::string::npos) << sixth->closing->reason;
  EXPECT_TRUE(join_from(server, "10.0.0.1", "room1", "Again")->welcome) << "a room that exists still admits";
  EXPECT_TRUE(join_from(server, "10.0.0.2", "room6", "Other")->welcome) << "another address creates rooms";
  EXPECT_EQ(server.core().abuse().count(Abuse::room_creation), 1u);
}

// --- rates -----------------------------------------------------------------------

TEST(RoomLimits, JoinsOverTheAddresssRateAreRefusedAcrossReconnects) {
  ServerConfig config = InMemoryServer::test_config();
  config.abuse.joins = {1.0 / 60, 3};
  InMemoryServer server(config);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(join_from(server, "10.0.0.1", "r", "Again")->welcome) << i;
  auto fourth = join_from(server, "10.0.0.1", "r", "Again");
  ASSERT_TRUE(fourth->closing);
  EXPECT_EQ(fourth->closing->code, CloseCode::rate_limited);
  EXPECT_NE(fourth->closing->reason.find("too many joins from your address; try again in"), std::string::npos)
      << fourth->closing->reason;
  EXPECT_TRUE(join_from(server, "10.0.0.2", "r", "Other")->welcome);
  EXPECT_EQ(server.core().abuse().count(Abuse::join_rate), 1u);
}

TEST(RoomLimits, JoinsIntoOneRoomFromManyAddressesHaveARate) {
  // Each address within its own rate, the room's together over it: the
  // room refuses; another room is not affected.
  ServerConfig config = InMemoryServer::test_config();
  config.abuse.room_joins = {1.0 / 60, 3};
  InMemoryServer server(config);
  std::vector<std::unique_ptr<InMemoryPeer>> present;  // they stay: an empty room would close and start afresh
  for (int i = 0; i < 3; ++i) {
    present.push_back(join_from(server, "10.0.1." + std::to_string(i), "busy", "P" + std::to_string(i)));
    EXPECT_TRUE(present.back()->welcome) << i;
  }
  auto fourth = join_from(server, "10.0.1.9", "busy", "Late");
  ASSERT_TRUE(fourth->closing);
  EXPECT_EQ(fourth->closing->code, CloseCode::rate_limited);
  EXPECT_NE(fourth->closing->reason.find("takes no more joins this moment; try again in"), std::string::npos)
      << fourth->closing->reason;
  EXPECT_TRUE(join_from(server, "10.0.1.9", "quiet", "Late")->welcome);
  EXPECT_EQ(server.core().abuse().count(Abuse::join_rate), 1u);
}

bool told(const InMemoryPeer& peer, const std::string& words) {
  for (const auto& line : peer.chat)
    if (line.from == 0 && line.text.find(words) != std::string::npos) return true;
  return false;
}

std::size_t lines_from_people(const InMemoryPeer& peer) {
  std::size_t lines = 0;
  for (const auto& line : peer.chat) lines += line.from != 0;
  return lines;
}

TEST(RoomLimits, ChatOverTheAddresssRateIsDroppedAndItsWriterTold) {
  ServerConfig config = InMemoryServer::test_config();
  config.abuse.chat = {1.0 / 60, 3};
  InMemoryServer server(config);
  auto a = join_from(server, "10.0.0.1", "talk", "A");
  auto b = join_from(server, "10.0.0.1", "talk", "B");  // the same address: one rate
  auto reader = join_from(server, "10.0.0.2", "talk", "Reader");
  ASSERT_TRUE(a->welcome && b->welcome && reader->welcome);
  a->send(codec::Chat{0, "one"});
  a->send(codec::Chat{0, "two"});
  b->send(codec::Chat{0, "three"});
  EXPECT_TRUE(reader->read_until([&] { return lines_from_people(*reader) >= 3; }));
  b->send(codec::Chat{0, "four"});
  EXPECT_TRUE(b->read_until([&] { return told(*b, "too many chat lines from your address"); }));
  reader->read_for(300ms);
  EXPECT_EQ(lines_from_people(*reader), 3u);
  EXPECT_FALSE(b->session().gone()) << "a dropped line does not cost the connection";
  EXPECT_EQ(server.core().abuse().count(Abuse::chat_rate), 1u);
}

TEST(RoomLimits, ChatOverTheRoomsRateIsDroppedAndItsWriterTold) {
  ServerConfig config = InMemoryServer::test_config();
  config.abuse.room_chat = {1.0 / 60, 3};
  InMemoryServer server(config);
  std::vector<std::unique_ptr<InMemoryPeer>> writers;
  for (int i = 1; i <= 4; ++i) {
    writers.push_back(join_from(server, "10.0.0." + std::to_string(i), "talk", "W" + std::to_string(i)));
    ASSERT_TRUE(writers.back()->welcome);
  }
  for (int i = 0; i < 3; ++i) writers[i]->send(codec::Chat{0, "line"});
  EXPECT_TRUE(writers[0]->read_until([&] { return lines_from_people(*writers[0]) >= 3; }));
  writers[3]->send(codec::Chat{0, "one too many"});
  EXPECT_TRUE(writers[3]->read_until([&] { return told(*writers[3], "not sent: room 'talk' carries at most"); }));
  writers[0]->read_for(300ms);
  EXPECT_EQ(lines_from_people(*writers[0]), 3u);
  EXPECT_EQ(server.core().abuse().count(Abuse::chat_rate), 1u);
}

// A line longer than a face may take to say (15 s) is said in part, and
// its writer told; lines written faster than they are said wait, a few at
// most, and the writer of one more is told it is shown but not said.
TEST(RoomLimits, SpeechLongerThanTheLimitIsSaidInPartAndItsWriterTold) {
  InMemoryServer server(InMemoryServer::test_config());
  auto a = join_from(server, "10.0.0.1", "talk", "A");
  auto reader = join_from(server, "10.0.0.2", "talk", "Reader");
  ASSERT_TRUE(a->welcome && reader->welcome);
  std::string long_line;
  while (long_line.size() + 12 < codec::kMaxChatBytes) long_line += "one more word ";
  a->send(codec::Chat{0, long_line});
  EXPECT_TRUE(a->read_until([&] { return told(*a, "your line was said in part"); }));
  for (int i = 0; i < 4; ++i) a->send(codec::Chat{0, "and then"});
  EXPECT_TRUE(a->read_until([&] { return told(*a, "your line is shown but not said"); }));
  EXPECT_TRUE(reader->read_until([&] { return lines_from_people(*reader) >= 5; })) << "every line is shown";
}

}  // namespace
}  // namespace fw::server
