// A real server and real clients on loopback: three people in a room see
// and hear one another, come and go, and a dropped link heals itself.
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "fw/model/file_io.hpp"
#include "fw/render/image_codec.hpp"
#include "room_harness.hpp"
#include "throttling_proxy.hpp"

namespace fw::test {
namespace {

using namespace std::chrono_literals;

// Whether any of the frames in `directory` shows `count` faces in their seats.
bool some_frame_shows(const std::filesystem::path& directory, int count) {
  for (const auto& file : frame_files(directory))
    if (shows_faces_at_every_seat(read_png(file), count)) return true;
  return false;
}

// The index of the first event of `kind` by `name` at or after `from`, or -1.
int find_event(const nlohmann::json& summary, const std::string& kind, const std::string& name, int from = 0,
               const std::string& text = "") {
  const auto& events = summary.value("events", nlohmann::json::array());
  for (int i = from; i < static_cast<int>(events.size()); ++i) {
    const auto& event = events[static_cast<std::size_t>(i)];
    if (event.value("kind", "") == kind && event.value("name", "") == name && (text.empty() || event.value("text", "") == text))
      return i;
  }
  return -1;
}

const char* kFrames = " --size 320x180 --fps 3 --samples 0 -q";

TEST(Room, ThreePeopleSeeEachOtherChatAndComeAndGo) {
  RoomServer server;
  ASSERT_GT(server.http_port(), 0) << "facewire-server did not start";
  ASSERT_GT(server.tcp_port(), 0) << "facewire-server did not say where its TCP port is";
  const std::string package = astronaut_package();
  ASSERT_FALSE(package.empty()) << "facewire-server prep failed on the astronaut portrait";
  const auto dir_a = fresh_directory("alice"), dir_b = fresh_directory("bob"), dir_c = fresh_directory("carol");

  // Alice uploads a photo over WebSocket, Bob a prepared package and speaks
  // TCP, Carol has no picture (the server draws her a face), joins last,
  // says hello and leaves first; Alice leaves before Bob.
  ClientRun alice("alice", server.ws_url() + " --room e2e --name alice --photo " + astronaut_photo() +
                               " --seconds 14 --out " + dir_a.string() + kFrames);
  ClientRun bob("bob", server.tcp_url() + " --api " + server.api_url() + " --room e2e --name bob --avatar " + package +
                           " --seconds 30 --out " + dir_b.string() + kFrames);
  ASSERT_TRUE(server.wait_for_room("e2e", 2, 60)) << "alice and bob never got in";
  ClientRun carol("carol", server.ws_url() + " --room e2e --name carol --say 'hello from carol' --seconds 5 --out " +
                               dir_c.string() + kFrames);
  carol.wait();
  alice.wait();
  bob.wait();
  for (const ClientRun* run : {&alice, &bob, &carol}) ASSERT_EQ(run->status(), 0) << run->transcript();

  // Carol saw and drew all three.
  const auto& seen_by_carol = carol.summary();
  EXPECT_EQ(seen_by_carol.at("avatars_seen"), 3) << carol.transcript();
  for (const char* name : {"alice", "bob", "carol"})
    EXPECT_GT(seen_by_carol.at("frames_per_avatar").value(name, 0), 0) << name << "\n" << carol.transcript();
  const auto carol_frames = frame_files(dir_c);
  ASSERT_FALSE(carol_frames.empty());
  EXPECT_TRUE(shows_faces_at_every_seat(read_png(carol_frames.back()), 3)) << carol_frames.back();
  EXPECT_GE(find_event(seen_by_carol, "chat", "carol", 0, "hello from carol"), 0) << "the writer gets her own line back";

  // Alice and Bob saw Carol come, speak and go, and drew the room of three.
  for (const ClientRun* run : {&alice, &bob}) {
    const auto& summary = run->summary();
    const int joined = find_event(summary, "joined", "carol");
    EXPECT_GE(joined, 0) << run->transcript();
    EXPECT_GT(find_event(summary, "chat", "carol", joined, "hello from carol"), joined) << run->transcript();
    EXPECT_GT(find_event(summary, "left", "carol", joined), joined) << run->transcript();
    EXPECT_EQ(summary.at("avatars_seen"), 3) << run->transcript();
  }
  EXPECT_EQ(alice.summary().at("avatars_with_package"), 2) << "alice and bob, at the end\n" << alice.transcript();
  EXPECT_GE(find_event(bob.summary(), "left", "alice"), 0) << bob.transcript();
  EXPECT_TRUE(some_frame_shows(dir_a, 3)) << "alice never drew the room of three";
  EXPECT_TRUE(some_frame_shows(dir_b, 3)) << "bob never drew the room of three";
  EXPECT_TRUE(shows_faces_at_every_seat(read_png(frame_files(dir_a).back()), 2)) << "after carol left, two remain";
  for (const auto& dir : {dir_a, dir_b, dir_c}) std::filesystem::remove_all(dir);
}

TEST(Room, AClientComesBackAfterItsLinkDrops) {
  RoomServer server;
  ASSERT_GT(server.http_port(), 0) << "facewire-server did not start";
  LinkShape fast;
  fast.bits_per_second = 50e6;
  fast.delay = 1ms;
  fast.queue_bytes = 1 << 20;
  fast.packet_bytes = 16 * 1024;
  ThrottlingProxy proxy("127.0.0.1", server.http_port(), fast, fast);
  const auto dir = fresh_directory("dave");
  ClientRun dave("dave", "ws://127.0.0.1:" + std::to_string(proxy.port()) + "/ --room heal --name dave --seconds 14 --out " +
                             dir.string() + kFrames);
  ClientRun erin("erin", server.ws_url() + " --room heal --name erin --seconds 18 -q");
  ASSERT_TRUE(server.wait_for_room("heal", 2, 30)) << "dave and erin never got in";
  std::this_thread::sleep_for(2s);
  proxy.drop_connections();
  dave.wait();
  erin.wait();
  ASSERT_EQ(dave.status(), 0) << dave.transcript();
  ASSERT_EQ(erin.status(), 0) << erin.transcript();
  EXPECT_GE(dave.summary().at("reconnects"), 1) << dave.transcript();
  const int left = find_event(erin.summary(), "left", "dave");
  EXPECT_GE(left, 0) << erin.transcript();
  EXPECT_GT(find_event(erin.summary(), "joined", "dave", left), left) << "dave came back\n" << erin.transcript();
  const auto frames = frame_files(dir);
  ASSERT_FALSE(frames.empty());
  EXPECT_TRUE(shows_faces_at_every_seat(read_png(frames.back()), 2)) << "after the drop dave sees both faces again";
  std::filesystem::remove_all(dir);
}

// A person at a terminal talks: lines typed on standard input and a file of
// timed lines go out while the client is in the room, and the others get
// them at their times.
TEST(Room, NativeClientsChatWhileJoined) {
  RoomServer server;
  ASSERT_GT(server.http_port(), 0) << "facewire-server did not start";
  const auto dir = fresh_directory("chat-lines");
  const auto script = dir / "script.txt";
  const auto typed = dir / "typed.txt";
  std::ofstream(script) << "# two lines two seconds apart\n1 first scripted line\n3 second scripted line\n";
  std::ofstream(typed) << "typed before joining\nand another\n";
  ClientRun listener("listener", server.ws_url() + " --room talk --name listener --seconds 12 -q");
  ASSERT_TRUE(server.wait_for_room("talk", 1, 30)) << "the listener never got in";
  ClientRun writer("writer", server.ws_url() + " --room talk --name writer --seconds 6 -q --chat " + script.string());
  ClientRun typist("typist", server.ws_url() + " --room talk --name typist --seconds 5 -q --chat - <" + typed.string());
  writer.wait();
  typist.wait();
  listener.wait();
  for (const ClientRun* run : {&listener, &writer, &typist}) ASSERT_EQ(run->status(), 0) << run->transcript();
  const auto& heard = listener.summary();
  const auto at = [&](const std::string& name, const std::string& text) {
    const int i = find_event(heard, "chat", name, 0, text);
    return i < 0 ? -1.0 : heard.at("events")[static_cast<std::size_t>(i)].value("at_s", -1.0);
  };
  const double first = at("writer", "first scripted line"), second = at("writer", "second scripted line");
  ASSERT_GE(first, 0) << listener.transcript();
  ASSERT_GE(second, 0) << listener.transcript();
  EXPECT_NEAR(second - first, 2.0, 0.5) << "the script's times";
  EXPECT_GE(at("typist", "typed before joining"), 0) << listener.transcript();
  EXPECT_GE(at("typist", "and another"), 0) << listener.transcript();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fw::test
