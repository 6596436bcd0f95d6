// Room, driven through in-memory connections on a real worker pool ticking
// at 30 Hz: joining and leaving, presence, chat, commands, the room's size,
// its autonomous avatars, and the stream each subscriber gets: every face,
// every package (previews first), within its budget, and the latest value
// rather than a growing queue when the subscriber does not read.
#include "room.hpp"

#include <algorithm>
#include <functional>
#include <future>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "in_memory_server.hpp"
#include "monotonic_clock.hpp"

namespace fw::server {
namespace {

using codec::CloseCode;
using test::eventually;
using test::HelloOptions;
using test::InMemoryPeer;
using test::InMemoryServer;
using namespace std::chrono_literals;

/// Seats `count` autonomous avatars (the demo faces) in `room_name` and waits until they sit.
std::shared_ptr<Room> room_with_autonomous_avatars(InMemoryServer& server, const std::string& room_name,
                                                   std::size_t count) {
  auto room = server.core().rooms().find_or_create(room_name, /*persistent=*/true);
  for (std::size_t i = 0; i < count; ++i) {
    JoinRequest request;
    request.name = "Auto" + std::to_string(i);
    request.avatar = server.core().demo_avatars().at(i);
    room->join(std::move(request));
  }
  std::promise<void> seated;
  room->then([&seated] { seated.set_value(); });
  seated.get_future().wait();
  return room;
}

TEST(InMemoryRoom, AJoinerIsWelcomedWithEveryoneAndTheOthersAreTold) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  ASSERT_EQ(bob->welcome->avatars.size(), 2u);
  EXPECT_EQ(bob->welcome->avatars[0].name, "Ann");
  EXPECT_TRUE(bob->welcome->avatars[0].person);
  EXPECT_EQ(bob->welcome->avatars[1].id, bob->welcome->you);
  ASSERT_TRUE(ann->read_until([&] { return !ann->presence.empty(); }));
  EXPECT_EQ(ann->presence[0].change, codec::Presence::Change::joined);
  EXPECT_EQ(ann->presence[0].avatar.id, bob->welcome->you);
  EXPECT_EQ(ann->presence[0].avatar.name, "Bob");
  const auto room = server.core().rooms().find_or_create("r");
  EXPECT_EQ(room->person_count(), 2u);
  EXPECT_EQ(room->avatar_count(), 2u);
  EXPECT_EQ(server.core().metrics().avatars.load(), 2);
}

TEST(InMemoryRoom, LeavingIsToldToTheOthersAndTheLastToLeaveClosesTheRoom) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  const std::uint32_t bob_id = bob->welcome->you;
  bob.reset();  // hangs up
  ASSERT_TRUE(ann->read_until([&] { return ann->presence.size() >= 2; }));
  EXPECT_EQ(ann->presence[1].change, codec::Presence::Change::left);
  EXPECT_EQ(ann->presence[1].avatar.id, bob_id);
  ASSERT_EQ(server.core().rooms().list().size(), 1u);
  ann.reset();
  EXPECT_TRUE(eventually([&] { return server.core().rooms().list().empty(); })) << "an empty room closes";
  EXPECT_TRUE(eventually([&] { return server.core().metrics().rooms.load() == 0; }));
}

TEST(InMemoryRoom, APersistentRoomStaysWithItsAutonomousAvatars) {
  InMemoryServer server(InMemoryServer::test_config(2));
  room_with_autonomous_avatars(server, "lobby", 2);
  {
    auto visitor = server.join("lobby", "Visitor");
    ASSERT_TRUE(visitor->welcome);
    ASSERT_EQ(visitor->welcome->avatars.size(), 3u);
    EXPECT_FALSE(visitor->welcome->avatars[0].person);
    EXPECT_EQ(visitor->welcome->avatars[0].name, "Auto0");
  }
  std::this_thread::sleep_for(50ms);
  const auto rooms = server.core().rooms().list();
  ASSERT_EQ(rooms.size(), 1u);
  EXPECT_EQ(rooms[0].avatars, 2u);
  EXPECT_EQ(rooms[0].persons, 0u);
}

TEST(InMemoryRoom, ChatReachesEveryoneTheWriterIncluded) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  bob->send(codec::Chat{0, "hello, Ann"});
  ASSERT_TRUE(ann->read_until([&] { return !ann->chat.empty(); }));
  ASSERT_TRUE(bob->read_until([&] { return !bob->chat.empty(); }));
  EXPECT_EQ(ann->chat[0].text, "hello, Ann");
  EXPECT_EQ(ann->chat[0].from, bob->welcome->you) << "the server says who wrote, whatever the client claimed";
  EXPECT_EQ(server.core().metrics().chat_lines.load(), 1u);
  bob->send(codec::Chat{0, ""});
  bob->read_for(100ms);
  EXPECT_EQ(bob->chat.size(), 1u) << "an empty line is dropped";
}

TEST(InMemoryRoom, ChatReachesEveryoneAsItShowsWithoutCharactersThatActUnseen) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  // A right-to-left override, and a line separator that would start what
  // looks like Ann's line in Bob's.
  bob->send(codec::Chat{0, "pay \u202Elive\u202C\u2028Ann: ok"});
  ASSERT_TRUE(ann->read_until([&] { return !ann->chat.empty(); }));
  EXPECT_EQ(ann->chat[0].text, "pay liveAnn: ok");
  bob->send(codec::Chat{0, "\u200B\u200B"});
  bob->read_for(100ms);
  ASSERT_TRUE(bob->read_until([&] { return !bob->chat.empty(); }));
  EXPECT_EQ(bob->chat.size(), 1u) << "a line with nothing visible is dropped";
}

TEST(InMemoryRoom, CommandsAreAnsweredAcceptedOrRefusedAndTheConnectionStays) {
  InMemoryServer server;
  auto ann = server.join("r", "Ann");
  auto bob = server.join("r", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  codec::Command joy;
  joy.request_id = 7;
  joy.emotion = "joy";
  joy.intensity = 0.8f;
  joy.duration_ms = 2000;
  codec::Command glee = joy;
  glee.request_id = 8;
  glee.emotion = "glee";
  codec::Command look;
  look.request_id = 9;
  look.kind = codec::Command::Kind::look_at;
  look.target = ann->welcome->you;
  look.duration_ms = 1000;
  codec::Command look_nowhere = look;
  look_nowhere.request_id = 10;
  look_nowhere.target = 4242;
  codec::Command facs;
  facs.request_id = 11;
  facs.kind = codec::Command::Kind::facs;
  facs.sentence = "this is no FACS sentence";
  for (const auto& command : {joy, glee, look, look_nowhere, facs}) bob->send(command);
  ASSERT_TRUE(bob->read_until([&] { return bob->results.size() == 5; }));
  std::map<std::uint32_t, std::string> errors;
  for (const auto& result : bob->results) errors[result.request_id] = result.error;
  EXPECT_EQ(errors[7], "");
  EXPECT_NE(errors[8], "") << "an unknown emotion";
  EXPECT_EQ(errors[9], "");
  EXPECT_NE(errors[10], "") << "a target not in the room";
  EXPECT_EQ(errors[11].rfind("script 1:1: ", 0), 0u) << "a sentence that does not parse, answered where: " << errors[11];
  for (const auto& [id, error] : errors) EXPECT_LE(error.size(), codec::kMaxReasonBytes);
  EXPECT_FALSE(bob->closing);
  EXPECT_TRUE(ann->results.empty()) << "results go to the sender only";
}

TEST(InMemoryRoom, ARoomHoldsRoomSizeAvatarsItsOwnIncluded) {
  ServerConfig config = InMemoryServer::test_config();
  config.room_size = 3;
  InMemoryServer server(config);
  room_with_autonomous_avatars(server, "small", 1);
  auto one = server.join("small", "One");
  auto two = server.join("small", "Two");
  auto three = server.join("small", "Three");
  EXPECT_TRUE(one->welcome && two->welcome);
  ASSERT_TRUE(three->closing);
  EXPECT_EQ(three->closing->code, CloseCode::room_full);
  EXPECT_NE(three->closing->reason.find("is full (3 avatars)"), std::string::npos) << three->closing->reason;
  two.reset();
  EXPECT_TRUE(eventually([&] { return server.core().rooms().find_or_create("small")->person_count() == 1; }));
  auto four = server.join("small", "Four");
  EXPECT_TRUE(four->welcome) << "a seat that was given back is free again";
}

TEST(InMemoryRoom, TicksAtTheConfiguredRate) {
  ServerConfig config = InMemoryServer::test_config();
  config.tick_hz = 10;
  InMemoryServer server(config);
  auto peer = server.join("r", "Ann", {.timestamps = true, .no_packages = true});
  ASSERT_TRUE(peer->welcome);
  EXPECT_EQ(peer->welcome->tick_hz, 10);
  ASSERT_TRUE(peer->read_until([&] { return !peer->ticks.empty(); }));
  const auto [first_at, first_tick] = peer->ticks.front();
  peer->read_for(1000ms);
  const auto [last_at, last_tick] = peer->ticks.back();
  const double seconds = std::chrono::duration<double>(last_at - first_at).count();
  ASSERT_GT(seconds, 0.5);
  EXPECT_NEAR((last_tick - first_tick) / seconds, 10.0, 2.5) << "ticks a second";
}

TEST(InMemoryRoom, EveryFaceMovesAndEveryPackageArrivesPreviewsFirst) {
  InMemoryServer server(InMemoryServer::test_config(2));
  room_with_autonomous_avatars(server, "lobby", 2);
  auto peer = server.join("lobby", "Looker", {.max_bps = 400000});
  ASSERT_TRUE(peer->welcome);
  const auto& avatars = peer->welcome->avatars;
  const bool everything = peer->read_until(
      [&] {
        if (peer->frames_per_avatar.size() < avatars.size()) return false;
        for (const auto& a : avatars)
          if (!peer->packages[{a.id, 1}].complete()) return false;
        return true;
      },
      10s);
  EXPECT_TRUE(everything);
  EXPECT_TRUE(peer->errors.empty()) << peer->errors.front();
  ASSERT_EQ(peer->package_order.size(), 2 * avatars.size());
  for (std::size_t i = 0; i < avatars.size(); ++i) EXPECT_EQ(peer->package_order[i].second, 0) << "previews first";
  for (const auto& a : avatars) {
    EXPECT_EQ(peer->packages[std::pair(a.id, 0)].bytes.size(), a.preview_bytes);
    EXPECT_EQ(peer->packages[std::pair(a.id, 1)].bytes.size(), a.full_bytes);
  }
}

TEST(InMemoryRoom, AClientThatFetchesPackagesOverHttpGetsNoChunks) {
  InMemoryServer server;
  room_with_autonomous_avatars(server, "lobby", 1);
  auto peer = server.join("lobby", "Fetcher", {.no_packages = true});
  ASSERT_TRUE(peer->welcome);
  ASSERT_TRUE(peer->read_until([&] { return peer->frames_per_avatar.size() == 2; }));
  EXPECT_EQ(peer->package_bytes, 0u);
}

/// Bytes the session wrote over `duration`, after `settle` to let the stream reach its pace.
std::uint64_t bytes_written_over(InMemoryPeer& peer, std::chrono::milliseconds settle,
                                 std::chrono::milliseconds duration) {
  peer.read_for(settle);
  const std::uint64_t before = peer.session().bytes_written();
  const auto start = std::chrono::steady_clock::now();
  peer.read_for(duration);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return static_cast<std::uint64_t>(static_cast<double>(peer.session().bytes_written() - before) *
                                    (static_cast<double>(duration.count()) / 1000.0) / seconds);
}

TEST(InMemoryRoom, ASubscriberIsSentNoMoreThanItsBudget) {
  InMemoryServer server(InMemoryServer::test_config(3));
  room_with_autonomous_avatars(server, "lobby", 3);
  // Packages to send fill whatever the faces leave, so the stream runs at its budget.
  constexpr std::uint32_t kBudgetBps = 24000;
  auto peer = server.join("lobby", "Thin", {.max_bps = kBudgetBps});
  ASSERT_TRUE(peer->welcome);
  const std::uint64_t bytes = bytes_written_over(*peer, 500ms, 2000ms);
  const double budget_bytes = kBudgetBps / 8.0 * 2.0;
  EXPECT_LE(static_cast<double>(bytes), budget_bytes * 1.05) << "framing included";
  EXPECT_GE(static_cast<double>(bytes), budget_bytes * 0.6) << "and the budget is used";
  EXPECT_TRUE(peer->errors.empty()) << peer->errors.front();
}

TEST(InMemoryRoom, SetRateChangesTheBudgetAndZeroMeansTheDefault) {
  ServerConfig config = InMemoryServer::test_config(3);
  config.default_client_bps = 16000;
  InMemoryServer server(config);
  room_with_autonomous_avatars(server, "lobby", 3);
  auto peer = server.join("lobby", "Changer", {.max_bps = 64000});
  ASSERT_TRUE(peer->welcome);
  peer->send(codec::SetRate{12000});
  peer->read_for(300ms);
  const std::uint64_t lowered = bytes_written_over(*peer, 200ms, 2000ms);
  EXPECT_LE(static_cast<double>(lowered), 12000 / 8.0 * 2.0 * 1.05);
  ASSERT_TRUE(peer->link);
  EXPECT_LE(peer->link->target_bps, 12000u);
  peer->send(codec::SetRate{0});
  ASSERT_TRUE(peer->read_until([&] { return peer->link && peer->link->target_bps > 12000; }, 3s));
  EXPECT_LE(peer->link->target_bps, 16000u) << "0: the server's default";
}

TEST(InMemoryRoom, AResyncRequestIsServedAndTheStreamGoesOn) {
  InMemoryServer server;
  room_with_autonomous_avatars(server, "lobby", 1);
  auto peer = server.join("lobby", "Lost", {.no_packages = true});
  ASSERT_TRUE(peer->welcome);
  ASSERT_TRUE(peer->read_until([&] { return peer->room_frames > 0; }));
  std::vector<std::uint8_t> resync;
  codec::write_resync_request(std::vector<std::uint32_t>{peer->welcome->avatars[0].id}, resync);
  peer->send_bytes(resync);
  const auto frames = peer->room_frames;
  EXPECT_TRUE(peer->read_until([&] { return peer->room_frames > frames + 5; }));
  EXPECT_FALSE(peer->closing);
  EXPECT_TRUE(peer->errors.empty()) << peer->errors.front();
}

// Latest value wins: a subscriber that stops reading has ticks skipped
// instead of a queue that grows, and when it reads again the frames it gets
// are of now, not a backlog of the seconds it missed.
TEST(InMemoryRoom, ASubscriberThatStopsReadingHasTicksSkippedAndThenGetsTheNewestFaces) {
  InMemoryServer server(InMemoryServer::test_config(2));
  room_with_autonomous_avatars(server, "lobby", 2);
  // The packages still on their way fill the budget the faces leave.
  constexpr std::uint32_t kBudgetBps = 64000;
  auto peer = server.join("lobby", "Stalled", {.max_bps = kBudgetBps, .timestamps = true});
  ASSERT_TRUE(peer->welcome);
  ASSERT_TRUE(peer->read_until([&] { return peer->room_frames > 0; }, 3s));
  peer->read_for(300ms);

  peer->session().set_reading(false);
  const auto skipped_before = server.core().metrics().skipped_ticks.load();
  std::size_t most_queued = 0, queued_at_half = 0;
  for (int i = 0; i < 75; ++i) {  // 1.5 s: 45 ticks
    std::this_thread::sleep_for(20ms);
    most_queued = std::max(most_queued, peer->session().queued_bytes());
    if (i == 37) queued_at_half = peer->session().queued_bytes();
  }
  const std::size_t queued_at_end = peer->session().queued_bytes();
  const auto skipped = server.core().metrics().skipped_ticks.load() - skipped_before;
  EXPECT_GE(skipped, 20u) << "most of the 45 ticks (fewer on a busy machine) are skipped";
  // The stream stops at half a second of budget (4 KB here) and a message
  // on its way; a whole second of budget is a generous bound.
  EXPECT_LE(most_queued, kBudgetBps / 8) << "the queue stays short";
  EXPECT_LE(queued_at_end, queued_at_half + 64) << "and does not grow (a link statistics message a second)";

  const std::uint64_t resumed_us = monotonic_us();
  peer->session().set_reading(true);
  const std::size_t before = peer->server_times_us.size();
  const auto fresh = [&] {
    return std::any_of(peer->server_times_us.begin() + static_cast<std::ptrdiff_t>(before),
                       peer->server_times_us.end(), [&](std::uint64_t t) { return t >= resumed_us; });
  };
  ASSERT_TRUE(peer->read_until(fresh, 1s)) << "frames of now arrive at once";
  const auto stale = std::count_if(peer->server_times_us.begin() + static_cast<std::ptrdiff_t>(before),
                                   peer->server_times_us.end(), [&](std::uint64_t t) { return t < resumed_us; });
  EXPECT_LE(stale, 20) << "about half a second's worth, not the 45 ticks it missed";
  peer->read_for(300ms);
  EXPECT_TRUE(peer->errors.empty()) << peer->errors.front() << ": the encoders held, so every frame decodes";
  ASSERT_TRUE(peer->link);
  EXPECT_GT(peer->link->skipped_ticks, 0u) << "the client is told";
}

// Two people without a photo whose names choose the same procedural face
// (procedural_face_for: by the name's hash) are shown with different ones:
// two of one face cannot be told apart.
TEST(InMemoryRoom, TwoPeopleWithoutAPhotoNeverWearTheSameFace) {
  constexpr std::uint32_t kFaces = 4;
  InMemoryServer server(InMemoryServer::test_config(kFaces));
  const std::string first = "P0";
  std::string second;
  for (int i = 1; second.empty(); ++i) {
    const std::string name = "P" + std::to_string(i);
    if (std::hash<std::string>{}(name) % kFaces == std::hash<std::string>{}(first) % kFaces) second = name;
  }
  auto a = server.join("r", first);
  auto b = server.join("r", second);
  ASSERT_TRUE(a->welcome && b->welcome);
  std::map<std::uint32_t, std::string> assets;
  for (const codec::AvatarInfo& info : b->welcome->avatars) assets[info.id] = info.asset;
  ASSERT_EQ(assets.size(), 2u);
  EXPECT_NE(assets[a->welcome->you], assets[b->welcome->you]) << first << " and " << second << " look alike";
}

}  // namespace
}  // namespace fw::server
