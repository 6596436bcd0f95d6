// Faces bound to their owners, against the real server on loopback: a
// package anyone in a room downloads, uploaded again, is another avatar
// with another key and never opens the first; the same photo twice makes
// two avatars; a key handed out before ids were random still opens its
// avatar; and an uploader deletes their avatar with its key (nobody else
// can), after which whoever wore it is shown with a procedural face. The
// people come from different /24s of 127.0.0.0/8, as strangers would.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demo_faces.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "http_get.hpp"
#include "room_test_client.hpp"
#include "room_test_server.hpp"
#include "server_keys.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using codec::CloseCode;
using test::RoomTestClient;
using test::RunningServer;
using Transport = RoomTestClient::Transport;

// Three strangers, each from a network of their own.
const std::string kAlice = "127.0.1.10", kMallory = "127.0.2.20", kBob = "127.0.3.30";

/// An HTTP exchange from the local address `from` (read until the server closes).
test::HttpReply http_from(const std::string& from, int port, const std::string& raw, int timeout_s = 60) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return {};
  timeval timeout{timeout_s, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  sockaddr_in local{}, server{};
  local.sin_family = server.sin_family = AF_INET;
  ::inet_pton(AF_INET, from.c_str(), &local.sin_addr);
  server.sin_port = htons(static_cast<std::uint16_t>(port));
  server.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0 ||
      ::connect(fd, reinterpret_cast<sockaddr*>(&server), sizeof server) != 0) {
    ::close(fd);
    return {};
  }
  return test::http_exchange_on(fd, raw);
}

test::HttpReply upload_from(const std::string& from, int port, const std::string& type, const std::string& body) {
  return http_from(from, port,
                   "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\nContent-Type: " + type +
                       "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
}

test::HttpReply get_from(const std::string& from, int port, const std::string& path) {
  return http_from(from, port, "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
}

/// DELETE /api/avatars/ID, with `key` in X-Avatar-Key unless it is empty.
test::HttpReply delete_from(const std::string& from, int port, const std::string& asset, const std::string& key) {
  return http_from(from, port,
                   "DELETE /api/avatars/" + asset + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n" +
                       (key.empty() ? "" : "X-Avatar-Key: " + key + "\r\n") + "\r\n");
}

struct Uploaded {
  std::string asset, key;
};

Uploaded uploaded(const test::HttpReply& reply) {
  EXPECT_EQ(reply.status, 201) << reply.body;
  const auto answer = nlohmann::json::parse(reply.body, nullptr, false);
  if (!answer.is_object() || !answer.contains("asset") || !answer.contains("key")) return {};
  return {answer["asset"], answer["key"]};
}

/// A package of a face of its own (not one the server already has).
std::string a_package(std::uint32_t look) {
  const auto bytes = make_demo_package(look);
  return std::string(bytes.begin(), bytes.end());
}

/// A hello from `from` wearing `asset` with `key`, answered by a welcome or a closing.
std::unique_ptr<RoomTestClient> wear(const RunningServer& server, const std::string& from, const std::string& room,
                                     const std::string& name, const std::string& asset, const std::string& key) {
  auto client = std::make_unique<RoomTestClient>(Transport::tcp, server.tcp_port(), from);
  EXPECT_TRUE(client->connected());
  codec::Hello hello;
  hello.room = room;
  hello.name = name;
  hello.avatar = asset;
  hello.avatar_key = key;
  client->send_message(hello);
  client->pump_until([&] { return client->welcome.has_value() || client->closing.has_value(); }, 10s);
  return client;
}

std::string outcome(const RoomTestClient& client) {
  return client.closing ? client.closing->reason : client.welcome ? "welcomed" : "no answer";
}

const codec::AvatarInfo* info_named(const codec::Welcome& welcome, const std::string& name) {
  for (const auto& info : welcome.avatars)
    if (info.name == name) return &info;
  return nullptr;
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(AvatarOwnership, ACopyOfSomeonesPackageIsAnotherAvatarAndNeverOpensTheirs) {
  RunningServer server("--no-demo-room");
  const Uploaded alice = uploaded(upload_from(kAlice, server.http_port(), "application/x-facewire-avatar", a_package(7)));
  ASSERT_FALSE(alice.asset.empty());
  const auto alice_in = wear(server, kAlice, "r", "Alice", alice.asset, alice.key);
  ASSERT_TRUE(alice_in->welcome) << outcome(*alice_in);

  // Mallory joins the room, learns Alice's asset id from the welcome and
  // downloads her package as every member's client does, then uploads it.
  const auto mallory_in = wear(server, kMallory, "r", "Mallory", "", "");
  ASSERT_TRUE(mallory_in->welcome) << outcome(*mallory_in);
  const auto* seen = info_named(*mallory_in->welcome, "Alice");
  ASSERT_TRUE(seen);
  ASSERT_EQ(seen->asset, alice.asset);
  const auto package = get_from(kMallory, server.http_port(), "/api/packages/" + seen->asset);
  ASSERT_EQ(package.status, 200);
  EXPECT_EQ(package.body, a_package(7));
  const Uploaded copy = uploaded(upload_from(kMallory, server.http_port(), "application/x-facewire-avatar", package.body));
  ASSERT_FALSE(copy.asset.empty());
  EXPECT_NE(copy.asset, alice.asset) << "the copy is an avatar of its own";
  EXPECT_NE(copy.key, alice.key);

  // Her key does not open Alice's id; it opens her own copy only.
  const auto as_alice = wear(server, kMallory, "r2", "Mallory", alice.asset, copy.key);
  ASSERT_TRUE(as_alice->closing) << outcome(*as_alice);
  EXPECT_EQ(as_alice->closing->code, CloseCode::unauthorized);
  EXPECT_NE(as_alice->closing->reason.find("only who uploaded it"), std::string::npos) << as_alice->closing->reason;
  const auto as_copy = wear(server, kMallory, "r2", "Mallory", copy.asset, copy.key);
  ASSERT_TRUE(as_copy->welcome) << outcome(*as_copy);
  EXPECT_EQ(info_named(*as_copy->welcome, "Mallory")->asset, copy.asset);

  // Alice's own key still opens her face, from anywhere she goes.
  const auto alice_again = wear(server, kAlice, "r3", "Alice", alice.asset, alice.key);
  ASSERT_TRUE(alice_again->welcome) << outcome(*alice_again);
  EXPECT_EQ(info_named(*alice_again->welcome, "Alice")->asset, alice.asset);
}

TEST(AvatarOwnership, TheSamePhotoTwiceMakesTwoAvatarsEachWithItsOwnKey) {
  RunningServer server("--no-demo-room");
  const std::string photo = file_text(test::test_photo("grace_hopper.jpg"));
  ASSERT_FALSE(photo.empty());
  const Uploaded first = uploaded(upload_from(kAlice, server.http_port(), "image/jpeg", photo));
  const Uploaded second = uploaded(upload_from(kMallory, server.http_port(), "image/jpeg", photo));
  ASSERT_FALSE(first.asset.empty());
  ASSERT_FALSE(second.asset.empty());
  EXPECT_NE(first.asset, second.asset);
  EXPECT_NE(first.key, second.key);
  EXPECT_EQ(file_text(server.data() / "avatars" / (first.asset + ".photo")), photo) << "each keeps its photo";
  EXPECT_EQ(file_text(server.data() / "avatars" / (second.asset + ".photo")), photo);

  const auto crossed = wear(server, kMallory, "r", "Mallory", first.asset, second.key);
  ASSERT_TRUE(crossed->closing) << outcome(*crossed);
  EXPECT_EQ(crossed->closing->code, CloseCode::unauthorized);
  const auto mine = wear(server, kMallory, "r", "Mallory", second.asset, second.key);
  EXPECT_TRUE(mine->welcome) << outcome(*mine);
  const auto hers = wear(server, kAlice, "r", "Grace", first.asset, first.key);
  EXPECT_TRUE(hers->welcome) << outcome(*hers);
}

TEST(AvatarOwnership, AKeyHandedOutBeforeIdsWereRandomStillOpensItsAvatar) {
  RunningServer server("--no-demo-room");
  // An avatar stored by an older server: its id is its package's hash, and
  // its key the HMAC of that id, as the upload answered then.
  const std::string legacy_id = "5eed0f00d5eed0f00d5eed0f00d5eed0";
  const auto package = make_demo_package(9);
  std::string error;
  ASSERT_TRUE(model::write_file_atomically(server.data() / "avatars" / (legacy_id + ".fwa"), package, error)) << error;
  std::vector<std::uint8_t> server_key;
  ASSERT_TRUE(model::read_file(server.data() / "server.key", 64, server_key, error)) << error;
  const std::string old_key = avatar_key(std::string(server_key.begin(), server_key.end()), legacy_id);

  const auto owner = wear(server, kAlice, "r", "Alice", legacy_id, old_key);
  ASSERT_TRUE(owner->welcome) << outcome(*owner);
  EXPECT_EQ(info_named(*owner->welcome, "Alice")->asset, legacy_id);
  const auto other = wear(server, kMallory, "r", "Mallory", legacy_id, old_key.substr(1) + "A");
  EXPECT_TRUE(other->closing) << outcome(*other);
  // And it deletes it.
  EXPECT_EQ(delete_from(kAlice, server.http_port(), legacy_id, old_key).status, 204);
}

TEST(AvatarOwnership, OnlyTheUploaderDeletesAndWhoWoreItIsShownWithAProceduralFace) {
  RunningServer server;  // with the lobby: its faces are the server's own
  const int port = server.http_port();
  const Uploaded alice = uploaded(upload_from(kAlice, port, "application/x-facewire-avatar", a_package(11)));
  const Uploaded bob = uploaded(upload_from(kBob, port, "application/x-facewire-avatar", a_package(12)));
  ASSERT_FALSE(alice.asset.empty());
  ASSERT_FALSE(bob.asset.empty());
  auto alice_in = wear(server, kAlice, "r", "Alice", alice.asset, alice.key);
  ASSERT_TRUE(alice_in->welcome) << outcome(*alice_in);
  auto bob_in = wear(server, kBob, "r", "Bob", bob.asset, bob.key);
  ASSERT_TRUE(bob_in->welcome) << outcome(*bob_in);
  const std::uint32_t alice_id = info_named(*bob_in->welcome, "Alice")->id;
  const auto full = std::make_pair(alice_id, static_cast<int>(codec::PackageChunk::Quality::full));
  ASSERT_TRUE(bob_in->pump_until([&] { return bob_in->packages[full].complete(); }, 10s));
  EXPECT_EQ(std::string(bob_in->packages[full].bytes.begin(), bob_in->packages[full].bytes.end()), a_package(11));

  // Refused: no key, someone else's key, an id nobody uploaded, a face of the server's own.
  const auto no_key = delete_from(kMallory, port, alice.asset, "");
  EXPECT_EQ(no_key.status, 403) << no_key.body;
  EXPECT_NE(no_key.body.find("X-Avatar-Key"), std::string::npos) << no_key.body;
  const auto wrong_key = delete_from(kBob, port, alice.asset, bob.key);
  EXPECT_EQ(wrong_key.status, 403) << wrong_key.body;
  EXPECT_NE(wrong_key.body.find("only whoever uploaded it"), std::string::npos) << wrong_key.body;
  const auto unknown = delete_from(kMallory, port, "0123456789abcdef0123456789abcdef", alice.key);
  EXPECT_EQ(unknown.status, 404) << unknown.body;
  const auto lobby = wear(server, kMallory, "lobby", "Mallory", "", "");
  ASSERT_TRUE(lobby->welcome) << outcome(*lobby);
  const std::string server_face = lobby->welcome->avatars.at(0).asset;
  const auto resident = delete_from(kMallory, port, server_face, avatar_key("", server_face));
  EXPECT_EQ(resident.status, 403) << resident.body;
  EXPECT_NE(resident.body.find("server's own"), std::string::npos) << resident.body;
  ASSERT_EQ(get_from(kAlice, port, "/api/packages/" + alice.asset).status, 200) << "still there";

  // Alice deletes hers.
  const auto deleted = delete_from(kAlice, port, alice.asset, alice.key);
  EXPECT_EQ(deleted.status, 204) << deleted.body;
  const auto gone = get_from(kBob, port, "/api/packages/" + alice.asset);
  EXPECT_EQ(gone.status, 404);
  EXPECT_NE(gone.body.find("deleted"), std::string::npos) << gone.body;
  for (const char* suffix : {".fwa", ".preview.fwa", ".photo"})
    EXPECT_FALSE(std::filesystem::exists(server.data() / "avatars" / (alice.asset + suffix))) << suffix;
  EXPECT_EQ(delete_from(kAlice, port, alice.asset, alice.key).status, 404) << "deleted already";
  const auto again = wear(server, kAlice, "r2", "Alice", alice.asset, alice.key);
  ASSERT_TRUE(again->closing) << outcome(*again);
  EXPECT_EQ(again->closing->code, CloseCode::bad_request);
  EXPECT_NE(again->closing->reason.find("deleted"), std::string::npos) << again->closing->reason;

  // Bob, in the room with her, is sent another full package for her avatar:
  // the procedural face of her name, the one she would wear without a photo.
  const auto plain_alice = wear(server, kMallory, "r3", "Alice", "", "");
  ASSERT_TRUE(plain_alice->welcome) << outcome(*plain_alice);
  const auto procedural = get_from(kMallory, port, "/api/packages/" + info_named(*plain_alice->welcome, "Alice")->asset);
  ASSERT_EQ(procedural.status, 200);
  const auto shows = [&] {
    const auto& p = bob_in->packages[full];
    return p.complete() && std::string(p.bytes.begin(), p.bytes.end()) == procedural.body;
  };
  EXPECT_TRUE(bob_in->pump_until(shows, 10s)) << "Bob still sees Alice's deleted face";
  EXPECT_TRUE(bob_in->errors.empty()) << bob_in->errors.front();
  EXPECT_FALSE(bob_in->closing) << outcome(*bob_in);
  // Alice is still in the room, and newcomers are told her new face.
  const auto newcomer = wear(server, kMallory, "r", "Carol", "", "");
  ASSERT_TRUE(newcomer->welcome) << outcome(*newcomer);
  ASSERT_TRUE(info_named(*newcomer->welcome, "Alice"));
  EXPECT_EQ(info_named(*newcomer->welcome, "Alice")->asset, info_named(*plain_alice->welcome, "Alice")->asset);

  const auto metrics = get_from(kAlice, port, "/metrics");
  EXPECT_NE(metrics.body.find("facewire_refusals_total{kind=\"face_not_yours\"} 2"), std::string::npos)
      << "the deletions without the key";
  EXPECT_NE(metrics.body.find("facewire_deleted_avatars_total 1"), std::string::npos);
}

}  // namespace
}  // namespace fw::server
