// Who may be whom, against the real server on loopback: nobody wears a face
// they did not upload, a join token admits one named person at a time (the
// same person resumes after a drop), names cannot hide characters, and with
// --auth-secret the HTTP API asks for a token (metrics for the operator's
// secret).
#include <chrono>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "http_get.hpp"
#include "join_token.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"
#include "run_command.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;
using codec::CloseCode;

/// An upload; a photo's answer waits for its preparation, which the first
/// time loads the landmark model: seconds on a loaded machine.
test::HttpReply post(int port, const std::string& type, const std::string& body, const std::string& headers = "") {
  return test::http_exchange(port,
                             "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" + headers +
                                 "Content-Type: " + type + "\r\nContent-Length: " + std::to_string(body.size()) +
                                 "\r\n\r\n" + body,
                             60);
}

/// A hello over TCP, answered by a welcome or a closing message.
std::unique_ptr<RoomTestClient> say_hello(const RunningServer& server, const codec::Hello& hello) {
  auto client = std::make_unique<RoomTestClient>(Transport::tcp, server.tcp_port());
  client->send_message(hello);
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 10s);
  return client;
}

codec::Hello hello_for(const std::string& room, const std::string& name) {
  codec::Hello hello;
  hello.room = room;
  hello.name = name;
  return hello;
}

std::string refusal(const RoomTestClient& client) {
  return client.closing ? client.closing->reason : client.welcome ? "welcomed" : "no answer";
}

std::string mint(const std::string& room, const std::string& name) {
  const auto minted = test::run_command(
      test::bin("facewire-server") + " token --room " + room + " --name " + name + " --ttl 300 --auth-secret s3cret",
      /*with_stderr=*/false);
  EXPECT_EQ(minted.status, 0) << minted.output;
  return minted.output.substr(0, minted.output.find('\n'));
}

/// An avatar package of its own, uploaded: the lobby's first face with its
/// skin a shade off (a package upload is checked, not prepared: fast).
nlohmann::json upload_a_face(const RunningServer& server, const std::string& headers = "") {
  auto looker = test::join(server, Transport::tcp, "lobby", "Looker");
  EXPECT_TRUE(looker->welcome);
  const auto full = test::http_get(server.http_port(), "/api/packages/" + looker->welcome->avatars.at(0).asset);
  EXPECT_EQ(full.status, 200);
  const auto uploaded = post(server.http_port(), "application/x-facewire-avatar", full.body, headers);
  EXPECT_EQ(uploaded.status, 201) << uploaded.body;
  return nlohmann::json::parse(uploaded.body, nullptr, false);
}

TEST(Identity, NobodyWearsAFaceTheyDidNotUpload) {
  RunningServer server;
  const nlohmann::json mine = upload_a_face(server);
  ASSERT_TRUE(mine.contains("key")) << mine.dump();
  const std::string asset = mine["asset"], key = mine["key"];

  // The id is public: every client in a room sees it. Without the key, or
  // with another's, it is refused.
  for (const std::string& wrong : {std::string(), std::string("AAAAAAAAAAAAAAAAAAAAAA"), key.substr(1) + "A"}) {
    codec::Hello hello = hello_for("r", "Mallory");
    hello.avatar = asset;
    hello.avatar_key = wrong;
    const auto client = say_hello(server, hello);
    ASSERT_TRUE(client->closing) << "'" << wrong << "': " << refusal(*client);
    EXPECT_EQ(client->closing->code, CloseCode::unauthorized) << client->closing->reason;
    EXPECT_NE(client->closing->reason.find("key"), std::string::npos) << client->closing->reason;
  }
  codec::Hello hello = hello_for("r", "Owner");
  hello.avatar = asset;
  hello.avatar_key = key;
  const auto owner = say_hello(server, hello);
  ASSERT_TRUE(owner->welcome) << refusal(*owner);
  EXPECT_EQ(owner->welcome->avatars.back().asset, asset);

  const auto metrics = test::http_get(server.http_port(), "/metrics");
  EXPECT_NE(metrics.body.find("facewire_refusals_total{kind=\"face_not_yours\"} 3"), std::string::npos)
      << metrics.body.substr(0, 300);
}

TEST(Identity, ATokenAdmitsOnePersonAtATimeAndTheSamePersonResumes) {
  RunningServer server("--auth-secret s3cret --no-demo-room");
  const std::string token = mint("a", "Ann");
  codec::Hello hello = hello_for("a", "Ann");
  hello.token = token;
  const auto first = say_hello(server, hello);
  ASSERT_TRUE(first->welcome) << refusal(*first);
  ASSERT_FALSE(first->welcome->resume.empty());

  // Someone else with the same invitation, while Ann is connected.
  const auto second = say_hello(server, hello);
  ASSERT_TRUE(second->closing) << refusal(*second);
  EXPECT_EQ(second->closing->code, CloseCode::unauthorized);
  EXPECT_NE(second->closing->reason.find("in use"), std::string::npos) << second->closing->reason;
  // A resume key that is not the holder's does not help.
  hello.resume = "not-the-key";
  EXPECT_TRUE(say_hello(server, hello)->closing);

  // Ann again, after a drop the server has not seen: her welcome's resume
  // key takes the token over, and the old connection is told why it ends.
  hello.resume = first->welcome->resume;
  auto resumed = say_hello(server, hello);
  ASSERT_TRUE(resumed->welcome) << refusal(*resumed);
  ASSERT_TRUE(first->pump_until([&] { return first->closing.has_value(); }, 5s));
  EXPECT_NE(first->closing->reason.find("replaced"), std::string::npos) << first->closing->reason;

  // Once she leaves, the invitation is free again.
  resumed.reset();
  hello.resume.clear();
  std::unique_ptr<RoomTestClient> later;
  for (int tries = 0; tries < 50; ++tries) {
    later = say_hello(server, hello);
    if (later->welcome) break;
    std::this_thread::sleep_for(100ms);
  }
  EXPECT_TRUE(later->welcome) << refusal(*later);
}

TEST(Identity, ATokenWithoutANameOrForAnotherNameIsRefused) {
  RunningServer server("--auth-secret s3cret --no-demo-room");
  const auto now =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  codec::Hello hello = hello_for("a", "Anyone");
  hello.token = mint_join_token({"a", "", now + 300}, "s3cret");  // signed, but names nobody
  auto nameless = say_hello(server, hello);
  ASSERT_TRUE(nameless->closing) << refusal(*nameless);
  EXPECT_EQ(nameless->closing->code, CloseCode::unauthorized);
  EXPECT_NE(nameless->closing->reason.find("names nobody"), std::string::npos) << nameless->closing->reason;

  hello.token = mint("a", "Ann");
  hello.name = "Eve";
  auto wrong_name = say_hello(server, hello);
  ASSERT_TRUE(wrong_name->closing) << refusal(*wrong_name);
  EXPECT_NE(wrong_name->closing->reason.find("another name"), std::string::npos) << wrong_name->closing->reason;
}

TEST(Identity, NamesAreNormalisedAndCannotHideCharacters) {
  RunningServer server("--no-demo-room");
  for (const std::string name : {"\u202Eevil", "\u200B", "Ada\u200B", "Bo\u2067b"}) {
    const auto client = say_hello(server, hello_for("r", name));
    ASSERT_TRUE(client->closing) << refusal(*client);
    EXPECT_EQ(client->closing->code, CloseCode::bad_request);
    EXPECT_NE(client->closing->reason.find("invisible or control"), std::string::npos) << client->closing->reason;
  }
  const auto zoe = say_hello(server, hello_for("r", "Zoe\u0301"));  // e + combining acute
  ASSERT_TRUE(zoe->welcome) << refusal(*zoe);
  EXPECT_EQ(zoe->welcome->avatars.back().name, "Zo\u00e9") << "one spelling: NFC";
}

TEST(Identity, WithAnAuthSecretTheApiWantsATokenAndMetricsTheOperatorsSecret) {
  RunningServer server("--auth-secret s3cret --metrics-secret m3trics");
  const std::string for_a = mint("a", "Ann"), for_b = mint("b", "Bo");
  codec::Hello hello = hello_for("b", "Bo");
  hello.token = for_b;
  const auto bo = say_hello(server, hello);
  ASSERT_TRUE(bo->welcome) << refusal(*bo);

  // The room list: a token's holder sees its room alone, never the others.
  EXPECT_EQ(test::http_get(server.http_port(), "/api/rooms").status, 401);
  const auto seen_by_a = test::http_get(server.http_port(), "/api/rooms?token=" + for_a);
  ASSERT_EQ(seen_by_a.status, 200) << seen_by_a.body;
  EXPECT_EQ(seen_by_a.body.find("\"b\""), std::string::npos) << seen_by_a.body;
  EXPECT_EQ(seen_by_a.body.find("lobby"), std::string::npos) << seen_by_a.body;
  const auto seen_by_b = test::http_get(server.http_port(), "/api/rooms", "Authorization: Bearer " + for_b + "\r\n");
  EXPECT_NE(seen_by_b.body.find("\"b\""), std::string::npos) << seen_by_b.body;

  // Uploads: refused at the header without a token, taken with one.
  const auto refused = post(server.http_port(), "image/jpeg", std::string(1000, 'x'));
  EXPECT_EQ(refused.status, 401) << refused.body;
  EXPECT_NE(refused.body.find("token"), std::string::npos) << refused.body;
  const auto bad = post(server.http_port(), "image/jpeg", std::string(1000, 'x'), "Authorization: Bearer " + for_a + "x\r\n");
  EXPECT_EQ(bad.status, 401) << bad.body;
  std::ifstream photo_file(test::test_photo("grace_hopper.jpg"), std::ios::binary);
  const std::string photo((std::istreambuf_iterator<char>(photo_file)), std::istreambuf_iterator<char>());
  const auto uploaded = post(server.http_port(), "image/jpeg", photo, "Authorization: Bearer " + for_a + "\r\n");
  EXPECT_EQ(uploaded.status, 201) << uploaded.body;

  // Metrics: the operator's secret only.
  EXPECT_EQ(test::http_get(server.http_port(), "/metrics").status, 401);
  EXPECT_EQ(test::http_get(server.http_port(), "/metrics", "Authorization: Bearer " + for_a + "\r\n").status, 401);
  const auto metrics = test::http_get(server.http_port(), "/metrics", "Authorization: Bearer m3trics\r\n");
  EXPECT_EQ(metrics.status, 200);
  EXPECT_NE(metrics.body.find("facewire_refusals_total{kind=\"unauthorized\"}"), std::string::npos);
}

TEST(Identity, WithAnAuthSecretAndNoMetricsSecretMetricsAreClosed) {
  RunningServer server("--auth-secret s3cret --no-demo-room");
  const auto metrics = test::http_get(server.http_port(), "/metrics");
  EXPECT_EQ(metrics.status, 403);
  EXPECT_NE(metrics.body.find("--metrics-secret"), std::string::npos) << metrics.body;
}

}  // namespace
}  // namespace fw::server
