// Saved looks against the real server on loopback (PROTOCOL.md 8.2, command
// kind 6): kept with the avatar's key and refused without it or with
// another's, a bad script answered with where it is, the 17th look and an
// oversized script refused with what to do; a saved episode played by name
// in a room reddens its wearer's face in what another person receives; and
// the looks go with their avatar. People come from different /24s.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "saved_looks_client.hpp"

namespace fw::server {
namespace {

using namespace std::chrono_literals;
using test::look_request;
using test::OwnedAvatar;
using test::RunningServer;
using test::save_look;

const std::string kAlice = "127.0.1.10", kMallory = "127.0.2.20", kBob = "127.0.3.30";
const std::string kSmile = "ClearAllFrame\nBeginKeyFrame\n  12 2.0\nAnimate 5 \"smile\"\nend\n";

TEST(SavedLooks, AreKeptWithTheAvatarsKeyAndRefusedWithoutIt) {
  RunningServer server("--no-demo-room");
  const int port = server.http_port();
  const OwnedAvatar alice = test::upload_own_face(kAlice, port, 3);
  const OwnedAvatar mallory = test::upload_own_face(kMallory, port, 4);
  ASSERT_FALSE(alice.key.empty());
  ASSERT_FALSE(mallory.key.empty());

  const long refused_before = test::refusal_count(port, "face_not_yours");
  EXPECT_EQ(look_request(kMallory, port, "PUT", alice.asset, "smile", "", kSmile).status, 403);
  const auto others = look_request(kMallory, port, "PUT", alice.asset, "smile", mallory.key, kSmile);
  EXPECT_EQ(others.status, 403);
  EXPECT_NE(others.body.find("only whoever uploaded it"), std::string::npos) << others.body;
  EXPECT_EQ(look_request(kMallory, port, "GET", alice.asset, "", mallory.key).status, 403);
  EXPECT_EQ(test::refusal_count(port, "face_not_yours"), refused_before + 3);
  EXPECT_EQ(look_request(kAlice, port, "GET", std::string(32, 'a'), "", alice.key).status, 404);

  // A script that does not parse: where, as a room would answer it.
  const auto bad = save_look(kAlice, port, alice, "oops", "ClearAllFrame\nBeginKeyFrame\n  12 strong\nend\n");
  EXPECT_EQ(bad.status, 422);
  EXPECT_EQ(bad.body.rfind("script 3:", 0), 0u) << bad.body;
  const auto big = save_look(kAlice, port, alice, "big", std::string(5000, '#'));
  EXPECT_EQ(big.status, 413);
  EXPECT_NE(big.body.find("at most 4096"), std::string::npos) << big.body;
  const auto unnamed = save_look(kAlice, port, alice, "%E2%80%8B", kSmile);  // a zero-width space alone
  EXPECT_EQ(unnamed.status, 400) << unnamed.body;

  ASSERT_EQ(save_look(kAlice, port, alice, "blush%20slowly", test::kBlushLook).status, 200);
  for (int i = 1; i < 16; ++i)
    ASSERT_EQ(save_look(kAlice, port, alice, "smile" + std::to_string(i), kSmile).status, 200) << i;
  const auto seventeenth = save_look(kAlice, port, alice, "one too many", kSmile);
  EXPECT_EQ(seventeenth.status, 409);
  EXPECT_NE(seventeenth.body.find("delete one"), std::string::npos) << seventeenth.body;
  EXPECT_EQ(save_look(kAlice, port, alice, "smile1", kSmile + "\n").status, 200) << "a name saved again replaces it";

  const auto listed = look_request(kAlice, port, "GET", alice.asset, "", alice.key);
  ASSERT_EQ(listed.status, 200);
  const auto looks = nlohmann::json::parse(listed.body)["looks"];
  ASSERT_EQ(looks.size(), 16u);
  EXPECT_EQ(looks[0]["name"], "blush slowly");
  EXPECT_EQ(looks[0]["kinds"], nlohmann::json::array({"vascular"}));
  EXPECT_EQ(looks[0]["script"], test::kBlushLook);
  EXPECT_EQ(looks[1]["kinds"], nlohmann::json::array({"expression"}));

  EXPECT_EQ(look_request(kAlice, port, "DELETE", alice.asset, "smile2", alice.key).status, 204);
  EXPECT_EQ(look_request(kAlice, port, "DELETE", alice.asset, "smile2", alice.key).status, 404);
  EXPECT_EQ(save_look(kAlice, port, alice, "one too many", kSmile).status, 200) << "a place was freed";

  // Changes are rated per avatar (24 at once, then one every 10 s): a
  // script saving in a loop is told when to come back.
  test::HttpReply rated;
  for (int i = 0; i < 30 && rated.status != 429; ++i) rated = save_look(kAlice, port, alice, "smile1", kSmile);
  ASSERT_EQ(rated.status, 429);
  EXPECT_NE(rated.body.find("of this avatar; try again in"), std::string::npos) << rated.body;
  EXPECT_NE(rated.headers.find("Retry-After"), std::string::npos);

  // Deleted with the avatar: its file too.
  EXPECT_TRUE(std::filesystem::exists(server.data() / "avatars" / (alice.asset + ".looks")));
  const auto deleted = test::http_from(kAlice, port,
                                       "DELETE /api/avatars/" + alice.asset +
                                           " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\nX-Avatar-Key: " +
                                           alice.key + "\r\n\r\n");
  ASSERT_EQ(deleted.status, 204);
  EXPECT_FALSE(std::filesystem::exists(server.data() / "avatars" / (alice.asset + ".looks")));
  EXPECT_EQ(look_request(kAlice, port, "GET", alice.asset, "", alice.key).status, 404);
}

TEST(SavedLooks, ASavedEpisodePlayedByNameReddensItsWearerForOthers) {
  RunningServer server("--no-demo-room");
  const OwnedAvatar alice = test::upload_own_face(kAlice, server.http_port(), 5);
  ASSERT_FALSE(alice.key.empty());
  ASSERT_EQ(save_look(kAlice, server.http_port(), alice, "flushed", test::kBlushLook).status, 200);

  auto alice_in = test::wear_in(server.tcp_port(), kAlice, "tea", "Alice", alice);
  ASSERT_TRUE(alice_in->welcome);
  auto bob = test::join(server, test::RoomTestClient::Transport::tcp, "tea", "Bob");
  ASSERT_TRUE(bob->welcome);
  const std::uint32_t alice_id = alice_in->welcome->you;
  bob->pump_for(1500ms);
  const float before = test::largest_blush(*bob, alice_id);

  const auto unknown = test::play_look(*alice_in, 1, "nope");
  ASSERT_TRUE(unknown);
  EXPECT_NE(unknown->find("no look named 'nope'"), std::string::npos) << *unknown;
  const auto played = test::play_look(*alice_in, 2, "flushed");
  ASSERT_TRUE(played);
  EXPECT_EQ(*played, "");
  EXPECT_GT(test::blush_within(*bob, alice_id, before + 0.1f, 10s), before + 0.1f)
      << "the saved episode did not redden Alice's face as Bob receives it";

  // Bob wears a face the room gave him: one of the server's own, which
  // keeps no looks (nobody holds its key), and no looks of his own to play.
  std::string bobs_face;
  for (const auto& info : bob->welcome->avatars)
    if (info.id == bob->welcome->you) bobs_face = info.asset;
  ASSERT_FALSE(bobs_face.empty());
  const auto own = look_request(kBob, server.http_port(), "PUT", bobs_face, "mine", alice.key, kSmile);
  EXPECT_EQ(own.status, 403);
  EXPECT_NE(own.body.find("server's own faces"), std::string::npos) << own.body;
  const auto bobs = test::play_look(*bob, 3, "flushed");
  ASSERT_TRUE(bobs);
  EXPECT_NE(bobs->find("uploaded avatar"), std::string::npos) << *bobs;
}

}  // namespace
}  // namespace fw::server
