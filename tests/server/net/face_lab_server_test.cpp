// Face-lab previews on the real server over loopback sockets (PROTOCOL.md
// 5.16): one address gets its share of previews and no more, with a reason
// that says when to try again; the server's own limit holds for everyone
// else; a preview's room is not listed and nobody else can join it; its
// overrides are answered, a room's refused; a muscle set on it sends the
// preview's page its simulated surface (5.18), and nobody else.
#include <thread>

#include <gtest/gtest.h>

#include "http_get.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;
using codec::CloseCode;

/// A preview asked for from `from`, with its welcome or closing message.
std::unique_ptr<RoomTestClient> preview_from(const RunningServer& server, const std::string& from,
                                             const std::string& name) {
  auto client = std::make_unique<RoomTestClient>(Transport::tcp, server.tcp_port(), from);
  EXPECT_TRUE(client->connected()) << "from " << from;
  codec::Hello hello;
  hello.room = "lab";
  hello.name = name;
  hello.preview = true;
  client->send_message(hello);
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 5s);
  return client;
}

/// The answer to one command, or nullopt after 5 s.
std::optional<std::string> answer(RoomTestClient& client, codec::Command command) {
  const std::size_t before = client.results.size();
  client.send_message(command);
  if (!client.pump_until([&] { return client.results.size() > before; }, 5s)) return std::nullopt;
  return client.results.back().error;
}

codec::Command override_command(std::uint32_t id, codec::FaceOverride change) {
  codec::Command c;
  c.request_id = id;
  c.kind = codec::Command::Kind::override_face;
  c.override_face = change;
  return c;
}

TEST(FaceLabServer, PreviewsPerAddressAndPerServerAreRefusedWithAReason) {
  RunningServer server(test::kManyClientsFromOneAddress + "--previews-per-address 2 --max-previews 3");
  auto first = preview_from(server, "127.0.0.1", "Ada");
  auto second = preview_from(server, "127.0.0.1", "Ada");
  ASSERT_TRUE(first->welcome && second->welcome);
  EXPECT_EQ(first->welcome->avatars.size(), 1u) << "a preview is a room of one";
  EXPECT_NE(first->welcome->room, second->welcome->room) << "each preview is a room of its own";

  auto third = preview_from(server, "127.0.0.1", "Ada");
  ASSERT_TRUE(third->closing) << "the third preview from one address is refused";
  EXPECT_EQ(third->closing->code, CloseCode::rate_limited);
  EXPECT_NE(third->closing->reason.find("2 face-lab previews"), std::string::npos) << third->closing->reason;
  EXPECT_NE(third->closing->reason.find("try again in"), std::string::npos) << third->closing->reason;

  auto other = preview_from(server, "127.0.0.2", "Bo");
  ASSERT_TRUE(other->welcome) << "another address has its own share";
  auto past_server = preview_from(server, "127.0.0.3", "Cy");
  ASSERT_TRUE(past_server->closing) << "the server runs 3 at most";
  EXPECT_EQ(past_server->closing->code, CloseCode::server_full);
  EXPECT_NE(past_server->closing->reason.find("try again in"), std::string::npos) << past_server->closing->reason;

  // A page that goes frees its preview: the address may open one again.
  first.reset();
  std::unique_ptr<RoomTestClient> again;
  for (int attempt = 0; attempt < 50 && !(again && again->welcome); ++attempt) {
    again = preview_from(server, "127.0.0.1", "Ada");
    if (!again->welcome) std::this_thread::sleep_for(100ms);
  }
  EXPECT_TRUE(again && again->welcome) << "a closed preview still counted";
}

TEST(FaceLabServer, APreviewIsNotListedAndNobodyElseJoinsIt) {
  RunningServer server(test::kManyClientsFromOneAddress);
  auto lab = preview_from(server, "127.0.0.1", "Ada");
  ASSERT_TRUE(lab->welcome);
  const std::string room = lab->welcome->room;

  const auto listed = test::http_get(server.http_port(), "/api/rooms");
  ASSERT_EQ(listed.status, 200);
  EXPECT_EQ(listed.body.find(room), std::string::npos) << listed.body;
  EXPECT_EQ(listed.body.find("~lab"), std::string::npos) << listed.body;

  auto intruder = test::join(server, Transport::tcp, room, "Eve");
  ASSERT_TRUE(intruder->closing) << "a hello naming the preview's room got in";
  EXPECT_EQ(intruder->closing->code, CloseCode::bad_request);
  lab->pump_for(300ms);
  EXPECT_TRUE(lab->presence.empty()) << "the preview saw somebody join";
}

TEST(FaceLabServer, OverridesAreAnsweredInAPreviewAndRefusedInARoom) {
  RunningServer server(test::kManyClientsFromOneAddress);
  auto lab = preview_from(server, "127.0.0.1", "Ada");
  ASSERT_TRUE(lab->welcome);
  EXPECT_EQ(answer(*lab, override_command(1, {codec::OverridePart::emotion, 0, 0, 10000})), "");
  const auto unknown = answer(*lab, override_command(2, {codec::OverridePart::action_unit, 3, 0, 5000}));
  ASSERT_TRUE(unknown);
  EXPECT_NE(unknown->find("action unit 3"), std::string::npos) << *unknown;

  codec::Command check;
  check.request_id = 3;
  check.kind = codec::Command::Kind::check;
  check.sentence = "ClearAllFrame\nBeginKeyFrame\n  12 oops\nend\n";
  const auto checked = answer(*lab, check);
  ASSERT_TRUE(checked);
  EXPECT_EQ(checked->rfind("line 3, column ", 0), 0u) << *checked;

  auto room = test::join(server, Transport::tcp, "plain", "Bo");
  ASSERT_TRUE(room->welcome);
  const auto refused = answer(*room, override_command(4, {codec::OverridePart::emotion, 0, 0, 10000}));
  ASSERT_TRUE(refused);
  EXPECT_NE(refused->find("face-lab preview"), std::string::npos) << *refused;
}

TEST(FaceLabServer, AMuscleSetOnAPreviewSendsItsSurfaceToItsPageAloneAtMostTenTimesASecond) {
  RunningServer server(test::kManyClientsFromOneAddress);
  auto lab = preview_from(server, "127.0.0.1", "Ada");
  ASSERT_TRUE(lab->welcome);
  auto room = test::join(server, Transport::tcp, "plain", "Bo");
  ASSERT_TRUE(room->welcome);
  lab->pump_for(500ms);
  EXPECT_TRUE(lab->preview_surfaces.empty()) << "a neutral face has no residual to send";

  // The left zygomatic minor: half of AU 10's upper-lip raise, no unit's
  // shape alone, so much of its pull is beyond the action units.
  EXPECT_EQ(answer(*lab, override_command(1, {codec::OverridePart::muscle, 20, 0, 10000})), "");
  EXPECT_EQ(answer(*lab, override_command(2, {codec::OverridePart::skin_age, 0, 0, 6000})), "");
  const auto muscle_42 = answer(*lab, override_command(3, {codec::OverridePart::muscle, 42, 0, 10000}));
  ASSERT_TRUE(muscle_42);
  EXPECT_NE(muscle_42->find("muscle 42 does not exist"), std::string::npos) << *muscle_42;
  const auto start = std::chrono::steady_clock::now();
  lab->pump_for(2s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_FALSE(lab->preview_surfaces.empty()) << "the preview's page was sent no surface";
  EXPECT_LE(static_cast<double>(lab->preview_surfaces.size()), 10.0 * seconds + 3) << "more than ten a second";
  const codec::PreviewSurface& last = lab->preview_surfaces.back();
  EXPECT_EQ(last.avatar, lab->welcome->you);
  EXPECT_FALSE(last.moves.empty());
  EXPECT_TRUE(lab->errors.empty()) << lab->errors.front();

  room->pump_for(200ms);
  EXPECT_TRUE(room->preview_surfaces.empty()) << "a room's client was sent a preview surface";
  const auto refused = answer(*room, override_command(4, {codec::OverridePart::muscle, 20, 0, 10000}));
  ASSERT_TRUE(refused);
  EXPECT_NE(refused->find("face-lab preview"), std::string::npos) << *refused;

  // Reset: the face goes back to neutral and the residual with it.
  EXPECT_EQ(answer(*lab, override_command(5, {codec::OverridePart::reset, 0, 0, 0})), "");
  ASSERT_TRUE(lab->pump_until(
      [&] { return !lab->preview_surfaces.empty() && lab->preview_surfaces.back().moves.empty(); }, 5s))
      << "the residual did not go after a reset";
}

}  // namespace
}  // namespace fw::server
