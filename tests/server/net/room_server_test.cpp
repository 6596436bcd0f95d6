// The room server, started for real on loopback ports and spoken to over
// WebSocket and TCP with the protocol's own codec (server/PROTOCOL.md).
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "http_get.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"
#include "run_command.hpp"
#include "server_keys.hpp"
#include "server_process.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::join;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;

class RoomServerTest : public ::testing::TestWithParam<Transport> {
 protected:
  // Every test here joins from 127.0.0.1, into rooms of its own.
  static void SetUpTestSuite() { server_ = new RunningServer(test::kManyClientsFromOneAddress); }
  static void TearDownTestSuite() { delete server_; }
  static inline RunningServer* server_ = nullptr;
};

TEST_P(RoomServerTest, TheLobbyIsAliveWithPreviewsFirst) {
  ASSERT_GT(server_->tcp_port(), 0);
  auto client = join(*server_, GetParam(), "lobby", "Newcomer");
  ASSERT_TRUE(client->welcome) << (client->closing ? client->closing->reason : "no answer");
  const auto& welcome = *client->welcome;
  EXPECT_EQ(welcome.room, "lobby");
  ASSERT_EQ(welcome.avatars.size(), 4u);  // Ada, Bruno, Grace and the newcomer
  EXPECT_FALSE(welcome.avatars[0].person);
  EXPECT_EQ(welcome.avatars.back().id, welcome.you);
  EXPECT_TRUE(welcome.avatars.back().person);

  // Every face moves, and every package arrives: all previews before any full one.
  const bool everything = client->pump_until(
      [&] {
        if (client->frames_per_avatar.size() < 4) return false;
        for (const auto& a : welcome.avatars)
          if (!client->packages[{a.id, 1}].complete()) return false;
        return true;
      },
      15s);
  EXPECT_TRUE(everything);
  EXPECT_TRUE(client->stream_header);
  EXPECT_TRUE(client->errors.empty()) << client->errors.front();
  for (const auto& a : welcome.avatars) EXPECT_GT(client->frames_per_avatar[a.id], 0u) << a.name;
  ASSERT_GE(client->package_order.size(), 8u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(client->package_order[i].second, 0) << "preview first";
  for (const auto& [key, package] : client->packages) {
    model::AvatarPackage parsed;
    std::string error;
    EXPECT_TRUE(model::parse_avatar_package(package.bytes, parsed, error)) << error;
    const auto& info = *std::find_if(welcome.avatars.begin(), welcome.avatars.end(),
                                     [&](const codec::AvatarInfo& a) { return a.id == key.first; });
    EXPECT_EQ(package.bytes.size(), key.second == 0 ? info.preview_bytes : info.full_bytes);
  }
}

TEST_P(RoomServerTest, ChatPresenceAndCommands) {
  const std::string room = GetParam() == Transport::tcp ? "chat-tcp" : "chat-ws";
  auto ann = join(*server_, GetParam(), room, "Ann");
  ASSERT_TRUE(ann->welcome);
  EXPECT_EQ(ann->welcome->avatars.size(), 1u);
  auto bob = join(*server_, GetParam(), room, "Bob");
  ASSERT_TRUE(bob->welcome);
  ASSERT_EQ(bob->welcome->avatars.size(), 2u);
  const std::uint32_t bob_id = bob->welcome->you;

  EXPECT_TRUE(ann->pump_until([&] { return !ann->presence.empty(); }, 5s));
  ASSERT_FALSE(ann->presence.empty());
  EXPECT_EQ(ann->presence[0].change, codec::Presence::Change::joined);
  EXPECT_EQ(ann->presence[0].avatar.name, "Bob");

  bob->send_message(codec::Chat{0, "hello, Ann"});
  EXPECT_TRUE(ann->pump_until([&] { return !ann->chat.empty(); }, 5s));
  EXPECT_TRUE(bob->pump_until([&] { return !bob->chat.empty(); }, 5s));
  ASSERT_FALSE(ann->chat.empty());
  EXPECT_EQ(ann->chat[0].text, "hello, Ann");
  EXPECT_EQ(ann->chat[0].from, bob_id);

  codec::Command joy;
  joy.request_id = 7;
  joy.emotion = "joy";
  bob->send_message(joy);
  codec::Command glee = joy;
  glee.request_id = 8;
  glee.emotion = "glee";
  bob->send_message(glee);
  EXPECT_TRUE(bob->pump_until([&] { return bob->results.size() >= 2; }, 5s));
  ASSERT_EQ(bob->results.size(), 2u);
  EXPECT_EQ(bob->results[0].request_id, 7u);
  EXPECT_EQ(bob->results[0].error, "");
  EXPECT_NE(bob->results[1].error, "");

  bob.reset();  // leaves
  EXPECT_TRUE(ann->pump_until([&] { return ann->presence.size() >= 2; }, 5s));
  ASSERT_GE(ann->presence.size(), 2u);
  EXPECT_EQ(ann->presence[1].change, codec::Presence::Change::left);
  EXPECT_EQ(ann->presence[1].avatar.id, bob_id);
}

TEST_P(RoomServerTest, AMalformedMessageClosesOnlyItsSender) {
  const std::string room = GetParam() == Transport::tcp ? "bad-tcp" : "bad-ws";
  auto good = join(*server_, GetParam(), room, "Good");
  auto bad = join(*server_, GetParam(), room, "Bad");
  ASSERT_TRUE(good->welcome && bad->welcome);
  bad->send({0x84, 0x01, 0x05, 'a'});  // a chat line cut short
  EXPECT_TRUE(bad->pump_until([&] { return bad->closed(); }, 5s));
  ASSERT_TRUE(bad->closing);
  EXPECT_EQ(bad->closing->code, codec::CloseCode::protocol_error);
  EXPECT_NE(bad->closing->reason.find("cut short"), std::string::npos) << bad->closing->reason;

  EXPECT_TRUE(good->pump_until([&] { return good->presence.size() >= 2; }, 5s));  // Bad joined, Bad left
  const auto frames_before = good->room_frames;
  good->pump_for(1500ms);
  EXPECT_GT(good->room_frames, frames_before) << "the others' stream goes on";
  EXPECT_FALSE(good->closed());
}

TEST_P(RoomServerTest, AnOversizedMessageClosesOnlyItsSender) {
  const std::string room = GetParam() == Transport::tcp ? "big-tcp" : "big-ws";
  auto good = join(*server_, GetParam(), room, "Good");
  auto big = join(*server_, GetParam(), room, "Big");
  ASSERT_TRUE(good->welcome && big->welcome);
  std::vector<std::uint8_t> huge(codec::kMaxUpstreamMessageBytes + 1, 'x');
  huge[0] = 0x84;
  big->send(huge);
  EXPECT_TRUE(big->pump_until([&] { return big->closed(); }, 5s));
  if (GetParam() == Transport::tcp) {
    ASSERT_TRUE(big->closing);
    EXPECT_EQ(big->closing->code, codec::CloseCode::message_too_large);
  } else {
    EXPECT_EQ(big->websocket_close_code(), 1009);
  }
  const auto frames_before = good->room_frames;
  good->pump_for(1500ms);
  EXPECT_GT(good->room_frames, frames_before);
  EXPECT_FALSE(good->closed());
}

TEST_P(RoomServerTest, TooManyMessagesCloseTheSender) {
  auto client = join(*server_, GetParam(), GetParam() == Transport::tcp ? "flood-tcp" : "flood-ws", "Flood");
  ASSERT_TRUE(client->welcome);
  for (int i = 0; i < 300; ++i) client->send_message(codec::Ping{static_cast<std::uint32_t>(i), 0});
  EXPECT_TRUE(client->pump_until([&] { return client->closed(); }, 5s));
  ASSERT_TRUE(client->closing);
  EXPECT_EQ(client->closing->code, codec::CloseCode::rate_limited);
}

TEST_P(RoomServerTest, AHelloItCannotServeIsRefusedWithAReason) {
  auto client = join(*server_, GetParam(), "no spaces allowed", "Ann");
  ASSERT_TRUE(client->closing);
  EXPECT_EQ(client->closing->code, codec::CloseCode::bad_request);
  EXPECT_NE(client->closing->reason.find("room names"), std::string::npos);

  codec::Hello hello;
  hello.room = "lobby";
  hello.name = "Ann";
  hello.avatar = "00000000000000000000000000000000";
  auto unknown = std::make_unique<RoomTestClient>(GetParam(), server_->port(GetParam()));
  unknown->send_message(hello);
  unknown->pump_until([&] { return unknown->closing.has_value(); }, 5s);
  ASSERT_TRUE(unknown->closing);
  EXPECT_NE(unknown->closing->reason.find("upload it first"), std::string::npos);

  auto chat_first = std::make_unique<RoomTestClient>(GetParam(), server_->port(GetParam()));
  chat_first->send_message(codec::Chat{0, "hi"});
  chat_first->pump_until([&] { return chat_first->closing.has_value(); }, 5s);
  ASSERT_TRUE(chat_first->closing);
  EXPECT_EQ(chat_first->closing->code, codec::CloseCode::protocol_error);
}

INSTANTIATE_TEST_SUITE_P(Transports, RoomServerTest, ::testing::Values(Transport::websocket, Transport::tcp),
                         [](const auto& param_info) { return param_info.param == Transport::tcp ? "tcp" : "websocket"; });

TEST(RoomServerTokens, ATokenForRoomADoesNotOpenRoomB) {
  RunningServer server("--auth-secret s3cret --no-demo-room");
  const auto minted =
      test::run_command(test::bin("facewire-server") + " token --room a --name Ann --ttl 60 --auth-secret s3cret",
                        /*with_stderr=*/false);
  ASSERT_EQ(minted.status, 0);
  const std::string token = minted.output.substr(0, minted.output.find('\n'));

  auto in_a = join(server, Transport::websocket, "a", "Ann", token);
  EXPECT_TRUE(in_a->welcome) << (in_a->closing ? in_a->closing->reason : "");

  for (const auto& [room, name, with] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"b", "Ann", token}, {"a", "Eve", token}, {"a", "Ann", ""}, {"a", "Ann", token + "x"}}) {
    auto refused = join(server, Transport::tcp, room, name, with);
    EXPECT_FALSE(refused->welcome) << room << " " << name;
    ASSERT_TRUE(refused->closing) << room << " " << name;
    EXPECT_EQ(refused->closing->code, codec::CloseCode::unauthorized) << refused->closing->reason;
  }
  // The room list shows a token's holder the token's room alone: one for b.
  const auto for_b =
      test::run_command(test::bin("facewire-server") + " token --room b --name Ann --ttl 60 --auth-secret s3cret", false);
  const auto rooms = test::http_get(server.http_port(), "/api/rooms",
                                    "Authorization: Bearer " + for_b.output.substr(0, for_b.output.find('\n')) + "\r\n");
  ASSERT_EQ(rooms.status, 200) << rooms.body;
  EXPECT_EQ(rooms.body.find("\"b\""), std::string::npos) << "refused joins create no rooms";
}

TEST(RoomServerLimits, ARoomHasASize) {
  RunningServer server("--room-size 2 --no-demo-room" + test::kManyClientsFromOneAddress);
  auto one = join(server, Transport::tcp, "small", "One");
  auto two = join(server, Transport::tcp, "small", "Two");
  auto three = join(server, Transport::tcp, "small", "Three");
  EXPECT_TRUE(one->welcome && two->welcome);
  ASSERT_TRUE(three->closing);
  EXPECT_EQ(three->closing->code, codec::CloseCode::room_full);
}

TEST(RoomServerOperations, ReadsAConfigFile) {
  const auto file = std::filesystem::temp_directory_path() / ("fw-config-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(file) << "[serve]\nroom-size = 1\nno-demo-room = true\n";
  RunningServer server("--config " + file.string());
  auto first = join(server, Transport::tcp, "solo", "One");
  auto second = join(server, Transport::tcp, "solo", "Two");
  std::filesystem::remove(file);
  EXPECT_TRUE(first->welcome);
  ASSERT_TRUE(second->closing);
  EXPECT_EQ(second->closing->code, codec::CloseCode::room_full);
  EXPECT_EQ(test::http_get(server.http_port(), "/api/rooms").body, "{\"rooms\":[{\"avatars\":1,\"name\":\"solo\",\"persons\":1}]}\n");
}

TEST(RoomServerOperations, DrainsOnSigterm) {
  RunningServer server("--no-demo-room --drain-seconds 5");
  auto client = join(server, Transport::websocket, "r", "Ann");
  ASSERT_TRUE(client->welcome);
  ::kill(server.process().pid(), SIGTERM);
  EXPECT_TRUE(client->pump_until([&] { return client->closed(); }, 5s));
  ASSERT_TRUE(client->closing);
  EXPECT_EQ(client->closing->code, codec::CloseCode::shutting_down);
  EXPECT_EQ(client->websocket_close_code(), 1001);
  EXPECT_EQ(server.process().terminate(8000), 0);
}

TEST(RoomServerOperations, ReportsReadinessMetricsAndRooms) {
  RunningServer server;
  // Ready once the demo room's faces are seated: soon after it listens.
  const auto deadline = std::chrono::steady_clock::now() + 10s;
  while (test::http_get(server.http_port(), "/readyz").status != 200 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(20ms);
  EXPECT_EQ(test::http_get(server.http_port(), "/readyz").status, 200);
  const auto metrics = test::http_get(server.http_port(), "/metrics");
  EXPECT_EQ(metrics.status, 200);
  for (const char* family : {"facewire_connections ", "facewire_rooms 1", "facewire_avatars 3", "facewire_bytes_sent_total",
                             "facewire_avatar_frames_sent_total", "facewire_dropped_ticks_total",
                             "facewire_physics_share ", "facewire_kinematic_faces ",
                             "facewire_tick_duration_seconds_bucket{le=\"+Inf\"}"})
    EXPECT_NE(metrics.body.find(family), std::string::npos) << family;
  const auto rooms = nlohmann::json::parse(test::http_get(server.http_port(), "/api/rooms").body);
  ASSERT_EQ(rooms["rooms"].size(), 1u);
  EXPECT_EQ(rooms["rooms"][0]["name"], "lobby");
  EXPECT_EQ(rooms["rooms"][0]["avatars"], 3);
}

TEST(RoomServerRest, ListsTheLanguagesAHelloMayChooseWithoutAToken) {
  RunningServer server("--auth-secret s3cret --no-demo-room");
  const auto reply = test::http_get(server.http_port(), "/api/languages");
  ASSERT_EQ(reply.status, 200) << reply.body;
  const auto languages = nlohmann::json::parse(reply.body);
  EXPECT_EQ(languages["default"], "en");
  std::vector<std::string> codes;
  for (const auto& language : languages["languages"]) {
    codes.push_back(language["code"]);
    EXPECT_FALSE(language["name"].get<std::string>().empty()) << codes.back();
  }
  EXPECT_TRUE(std::is_sorted(codes.begin(), codes.end()));
  EXPECT_TRUE(std::adjacent_find(codes.begin(), codes.end()) == codes.end()) << "one entry per code";
  for (const char* code : {"de", "en", "en-us", "es", "fr", "pt-br"})
    EXPECT_NE(std::find(codes.begin(), codes.end(), code), codes.end()) << code;
}

test::HttpReply post(int port, const std::string& type, const std::string& body) {
  return test::http_exchange(port, "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
                                   "Content-Type: " + type + "\r\nContent-Length: " + std::to_string(body.size()) +
                                   "\r\n\r\n" + body);
}

TEST(RoomServerRest, UploadsAreCheckedAndServed) {
  RunningServer server("--max-upload-bytes 65536");
  auto client = join(server, Transport::websocket, "lobby", "Looker");
  ASSERT_TRUE(client->welcome);
  const std::string asset = client->welcome->avatars[0].asset;
  const auto full = test::http_get(server.http_port(), "/api/packages/" + asset);
  ASSERT_EQ(full.status, 200);
  EXPECT_EQ(full.body.size(), client->welcome->avatars[0].full_bytes);
  const auto preview = test::http_get(server.http_port(), "/api/packages/" + asset + "?quality=preview");
  ASSERT_EQ(preview.status, 200);
  EXPECT_LT(preview.body.size(), full.body.size());
  model::AvatarPackage parsed;
  std::string error;
  EXPECT_TRUE(model::parse_avatar_package(
      {reinterpret_cast<const std::uint8_t*>(preview.body.data()), preview.body.size()}, parsed, error))
      << error;
  EXPECT_EQ(test::http_get(server.http_port(), "/api/packages/../../etc/passwd").status, 404);

  // A package uploaded again is an avatar of its own (PROTOCOL.md 8.1): a
  // face someone downloaded is never theirs to wear under its own id.
  const auto again = post(server.http_port(), "application/x-facewire-avatar", full.body);
  ASSERT_EQ(again.status, 201) << again.body;
  EXPECT_NE(nlohmann::json::parse(again.body)["asset"], asset);

  EXPECT_EQ(post(server.http_port(), "application/x-facewire-avatar", "").status, 400);
  const auto wrong_type = post(server.http_port(), "text/plain", "hello");
  EXPECT_EQ(wrong_type.status, 415);
  EXPECT_NE(wrong_type.body.find("image/jpeg"), std::string::npos);
  const auto garbage = post(server.http_port(), "application/x-facewire-avatar", "FWAV but not really");
  EXPECT_EQ(garbage.status, 422);
  EXPECT_NE(garbage.body.find("not valid"), std::string::npos);
  const auto too_big = post(server.http_port(), "image/jpeg", std::string(70000, 'x'));
  EXPECT_EQ(too_big.status, 413);
  EXPECT_NE(too_big.body.find("smaller photo"), std::string::npos);
  // Refused from its first bytes, before the landmark model is loaded.
  const auto not_a_photo = post(server.http_port(), "image/png", "not a png");
  EXPECT_EQ(not_a_photo.status, 422);
  EXPECT_NE(not_a_photo.body.find("not an image"), std::string::npos) << not_a_photo.body;
}

TEST(RoomServerRest, UploadsAreLimitedPerAddressAndMinute) {
  RunningServer server("--no-demo-room");
  // Refused from their first bytes, but counted: preparing a photo costs a second of CPU.
  for (int i = 0; i < 6; ++i) EXPECT_EQ(post(server.http_port(), "image/png", "not a png").status, 422) << i;
  const auto seventh = post(server.http_port(), "image/png", "not a png");
  EXPECT_EQ(seventh.status, 429);
  EXPECT_NE(seventh.body.find("at most 6 uploads a minute"), std::string::npos) << seventh.body;
}

TEST(RoomServerRest, AClientHoldingItsOwnPackageIsNotSentItBack) {
  RunningServer server;
  // The lobby's first face as this client's own package, uploaded again.
  auto looker = join(server, Transport::tcp, "lobby", "Looker");
  ASSERT_TRUE(looker->welcome);
  const auto full = test::http_get(server.http_port(), "/api/packages/" + looker->welcome->avatars[0].asset);
  ASSERT_EQ(full.status, 200);
  const auto uploaded = post(server.http_port(), "application/x-facewire-avatar", full.body);
  ASSERT_EQ(uploaded.status, 201) << uploaded.body;

  RoomTestClient client(Transport::tcp, server.tcp_port());
  codec::Hello hello;
  hello.room = "lobby";
  hello.name = "Holder";
  hello.avatar = nlohmann::json::parse(uploaded.body)["asset"];
  hello.avatar_key = nlohmann::json::parse(uploaded.body)["key"];
  hello.own_package = true;
  client.send_message(hello);
  ASSERT_TRUE(client.pump_until([&] { return client.welcome.has_value() || client.closing.has_value(); }, 5s));
  ASSERT_TRUE(client.welcome) << (client.closing ? client.closing->reason : "no answer");
  const std::uint32_t you = client.welcome->you;
  // Every other face's full package arrives, and the own face moves, but
  // not one chunk of the own package comes down.
  const bool others = client.pump_until(
      [&] {
        for (const auto& a : client.welcome->avatars)
          if (a.id != you && !client.packages[{a.id, 1}].complete()) return false;
        return client.frames_per_avatar[you] > 0;
      },
      15s);
  EXPECT_TRUE(others);
  EXPECT_EQ(client.packages.count({you, 0}), 0u);
  EXPECT_EQ(client.packages.count({you, 1}), 0u);
}

std::string multipart(const std::string& boundary, const std::string& package, const std::string& photo) {
  return "--" + boundary + "\r\nContent-Disposition: form-data; name=\"package\"\r\n\r\n" + package + "\r\n--" +
         boundary + "\r\nContent-Disposition: form-data; name=\"photo\"\r\nContent-Type: image/png\r\n\r\n" + photo +
         "\r\n--" + boundary + "--\r\n";
}

/// `package` as a build of the previous generic face wrote it.
std::string out_of_date(const std::string& package) {
  model::AvatarPackage parsed;
  std::string error;
  EXPECT_TRUE(model::parse_avatar_package(
      {reinterpret_cast<const std::uint8_t*>(package.data()), package.size()}, parsed, error)) << error;
  parsed.generic_face_version -= 1;
  const auto bytes = model::serialize_avatar_package(parsed);
  return {bytes.begin(), bytes.end()};
}

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

TEST(RoomServerRest, StoredAvatarsKeepTheirPhotoAndArePreparedAgainFromIt) {
  RunningServer server;
  auto looker = join(server, Transport::tcp, "lobby", "Looker");
  ASSERT_TRUE(looker->welcome);
  const std::string lobby_package =
      test::http_get(server.http_port(), "/api/packages/" + looker->welcome->avatars[0].asset).body;
  const std::filesystem::path avatars = server.data() / "avatars";
  std::ifstream photo_file(test::test_photo("astronaut.png"), std::ios::binary);
  const std::string photo((std::istreambuf_iterator<char>(photo_file)), std::istreambuf_iterator<char>());

  // A package with the photo it was prepared from: both kept.
  model::AvatarPackage parsed;
  std::string error;
  ASSERT_TRUE(model::parse_avatar_package(
      {reinterpret_cast<const std::uint8_t*>(lobby_package.data()), lobby_package.size()}, parsed, error));
  parsed.skin_tone[0] ^= 1;  // another avatar than the lobby's
  const auto other = model::serialize_avatar_package(parsed);
  const std::string package(other.begin(), other.end());
  const auto both =
      post(server.http_port(), "multipart/form-data; boundary=b0undary", multipart("b0undary", package, photo));
  ASSERT_EQ(both.status, 201) << both.body;
  const std::string asset = nlohmann::json::parse(both.body)["asset"];
  std::vector<std::uint8_t> kept;
  ASSERT_TRUE(model::read_file(avatars / (asset + ".photo"), 1 << 24, kept, error)) << error;
  EXPECT_EQ(std::string(kept.begin(), kept.end()), photo);
  const auto no_photo_part = post(server.http_port(), "multipart/form-data; boundary=b", "--b--\r\n");
  EXPECT_EQ(no_photo_part.status, 400);
  EXPECT_NE(no_photo_part.body.find("'package'"), std::string::npos) << no_photo_part.body;

  // Avatars stored by a build of the previous generic face, one with its photo.
  const std::string with_photo = "00000000000000000000000000000001", without = "00000000000000000000000000000002";
  write_file(avatars / (with_photo + ".fwa"), out_of_date(package));
  write_file(avatars / (with_photo + ".photo"), photo);
  write_file(avatars / (without + ".fwa"), out_of_date(package));
  const auto busy = test::http_get(server.http_port(), "/api/packages/" + with_photo);
  EXPECT_EQ(busy.status, 503) << busy.body;
  EXPECT_NE(busy.headers.find("Retry-After: 5"), std::string::npos) << busy.headers;
  test::HttpReply served;
  for (int tries = 0; tries < 120 && served.status != 200; ++tries) {
    std::this_thread::sleep_for(250ms);
    served = test::http_get(server.http_port(), "/api/packages/" + with_photo);
  }
  ASSERT_EQ(served.status, 200) << served.body;
  EXPECT_TRUE(model::parse_avatar_package(
      {reinterpret_cast<const std::uint8_t*>(served.body.data()), served.body.size()}, parsed, error)) << error;
  EXPECT_NE(served.headers.find("Cache-Control: public, no-cache"), std::string::npos) << served.headers;

  RoomTestClient client(Transport::tcp, server.tcp_port());
  codec::Hello hello;
  hello.room = "elsewhere";
  hello.name = "Returning";
  hello.avatar = with_photo;
  // Stored by hand here, so the key is made as the server makes it, from its own key.
  std::vector<std::uint8_t> server_key;
  ASSERT_TRUE(model::read_file(server.data() / "server.key", 64, server_key, error)) << error;
  hello.avatar_key = avatar_key(std::string(server_key.begin(), server_key.end()), with_photo);
  client.send_message(hello);
  ASSERT_TRUE(client.pump_until([&] { return client.welcome.has_value() || client.closing.has_value(); }, 5s));
  ASSERT_TRUE(client.welcome) << (client.closing ? client.closing->reason : "no answer");
  EXPECT_EQ(client.welcome->avatars.at(0).asset, with_photo) << "the same id";

  const auto gone = test::http_get(server.http_port(), "/api/packages/" + without);
  EXPECT_EQ(gone.status, 410);
  EXPECT_NE(gone.body.find("upload your photo again"), std::string::npos) << gone.body;
  const auto metrics = test::http_get(server.http_port(), "/metrics").body;
  EXPECT_NE(metrics.find("facewire_repreparations_total 1\n"), std::string::npos);
  EXPECT_NE(metrics.find("facewire_outdated_avatars_total 1\n"), std::string::npos);
}

}  // namespace
}  // namespace fw::server
