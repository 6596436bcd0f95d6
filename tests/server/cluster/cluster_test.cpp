// A cluster on loopback: a real redis-server the test starts itself and
// real facewire-server nodes on it (server/CLUSTER.md). Clients spread over
// the nodes meet in one room; the room's owner is killed (SIGKILL) and
// another node takes it over; Redis restarts; a subscriber that stops
// reading on one node leaves the room's pace on another alone; messages
// forged straight into Redis change nothing a client sees.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "demo_faces.hpp"
#include "bridge_message.hpp"
#include "file_bytes.hpp"
#include "http_get.hpp"
#include "join_token.hpp"
#include "test_paths.hpp"
#include "redis_blocking.hpp"
#include "redis_process.hpp"
#include "room_test_server.hpp"
#include "cluster_fixture.hpp"
#include "saved_looks_client.hpp"

namespace fw::test {
namespace {

using namespace std::chrono_literals;
using Transport = RoomTestClient::Transport;
using Clock = std::chrono::steady_clock;

/// Two nodes, "a" and "b", with the default flags, each ready (its /readyz) within 20 s.
bool two_ready_nodes(Cluster& cluster) {
  cluster.add_node("a");
  cluster.add_node("b");
  for (std::size_t i = 0; i < 2; ++i)
    if (!eventually([&] { return ready(cluster.node(i).http_port()); }, 20s)) return false;
  return true;
}

/// Whether each client decodes frames of every one of `ids` (its own too).
bool everyone_sees(const std::vector<RoomTestClient*>& clients, const std::set<std::uint32_t>& ids) {
  for (RoomTestClient* c : clients)
    for (const std::uint32_t id : ids)
      if (c->frames_per_avatar[id] == 0) return false;
  return true;
}

/// Who decodes no frame of whom, for a failure's message: "client 1 (avatar
/// 3) sees nothing of 2; ...", or an empty string.
std::string unseen(const std::vector<RoomTestClient*>& clients, const std::set<std::uint32_t>& ids) {
  std::string text;
  for (std::size_t i = 0; i < clients.size(); ++i)
    for (const std::uint32_t id : ids)
      if (clients[i]->frames_per_avatar[id] == 0)
        text += "client " + std::to_string(i) + " (avatar " +
                std::to_string(clients[i]->welcome ? clients[i]->welcome->you : 0) + ") sees nothing of " +
                std::to_string(id) + "; ";
  return text;
}

TEST(Cluster, ThreeNodesOneRoomEveryoneSeesEveryone) {
  Cluster cluster;
  for (const char* name : {"a", "b", "c"}) cluster.add_node(name);
  for (std::size_t i = 0; i < 3; ++i)
    ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s)) << "node " << i << " not ready";
  std::vector<std::unique_ptr<RoomTestClient>> clients;
  std::vector<RoomTestClient*> all;
  for (std::size_t i = 0; i < 3; ++i) {
    // P1's lines are said in German: its language travels with its join to
    // whichever node owns the room.
    clients.push_back(join_node(cluster.node(i), "meet", "P" + std::to_string(i), "", "", i == 1 ? "de" : ""));
    all.push_back(clients.back().get());
  }
  std::set<std::uint32_t> ids;
  for (auto* c : all) ids.insert(c->welcome->you);
  ASSERT_EQ(ids.size(), 3u) << "each person has an id of their own";
  const auto start = Clock::now();
  while (Clock::now() - start < 30s && !everyone_sees(all, ids)) pump_all(all, 200ms);
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(known_avatars(*all[i]), ids) << "client on node " << i << " knows the room's three people";
    for (const std::uint32_t id : ids)
      EXPECT_GT(all[i]->frames_per_avatar[id], 0u) << "client on node " << i << " decodes no frame of avatar " << id;
    EXPECT_TRUE(all[i]->errors.empty()) << all[i]->errors.front();
  }
  // Chat goes everywhere, whichever node it was written on, and so does
  // the news that its writer's face begins to say it, in the writer's language.
  codec::Chat line;
  line.text = "hello from b";
  clients[1]->send_message(line);
  EXPECT_TRUE(eventually(
      [&] {
        pump_all(all, 50ms);
        for (auto* c : all) {
          bool heard = false;
          for (const auto& chat : c->chat) heard = heard || chat.text == "hello from b";
          if (!heard || c->speaking.empty()) return false;
        }
        return true;
      },
      10s));
  for (std::size_t i = 0; i < all.size(); ++i) {
    ASSERT_EQ(all[i]->speaking.size(), 1u) << "client on node " << i;
    const codec::Speaking& said = all[i]->speaking.front();
    EXPECT_EQ(said.avatar, clients[1]->welcome->you);
    EXPECT_EQ(said.language, "de") << "client on node " << i;
    EXPECT_EQ(said.text, "hello from b");
    EXPECT_GT(said.duration_ms, 500u);
    EXPECT_LT(all[i]->last_tick_before_speaking.front(), said.tick) << "client on node " << i << ": a frame of the line came first";
  }
  const std::string owner = cluster.owner_of("meet");
  EXPECT_FALSE(owner.empty()) << "the room has an owner in Redis";
}

TEST(Cluster, KillingTheOwnerTheRoomGoesOnWithinFiveSeconds) {
  Cluster cluster;
  for (const char* name : {"a", "b", "c"}) cluster.add_node(name);
  for (std::size_t i = 0; i < 3; ++i)
    ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  std::vector<std::unique_ptr<RoomTestClient>> clients;
  for (std::size_t i = 0; i < 3; ++i) clients.push_back(join_node(cluster.node(i), "meet", "P" + std::to_string(i)));
  std::vector<RoomTestClient*> all;
  std::set<std::uint32_t> ids;
  for (auto& c : clients) {
    all.push_back(c.get());
    ids.insert(c->welcome->you);
  }
  const auto warm = Clock::now();
  while (Clock::now() - warm < 30s && !everyone_sees(all, ids)) pump_all(all, 200ms);
  ASSERT_TRUE(everyone_sees(all, ids)) << "the room did not come together before the kill";

  const std::string owner = cluster.owner_of("meet");
  const std::size_t dead = cluster.index_of(owner);
  ASSERT_LT(dead, 3u) << "owner '" << owner << "' is not one of the nodes";
  const std::uint32_t dead_id = clients[dead]->welcome->you;
  const std::string dead_resume = clients[dead]->welcome->resume;
  std::vector<RoomTestClient*> survivors;
  for (std::size_t i = 0; i < 3; ++i)
    if (i != dead) survivors.push_back(all[i]);
  pump_all(survivors, 200ms);
  std::vector<std::uint64_t> frames_before;
  for (auto* c : survivors) frames_before.push_back(c->room_frames);
  std::vector<std::size_t> left_before;
  for (auto* c : survivors) left_before.push_back(c->presence.size());

  ::kill(cluster.node(dead).process().pid(), SIGKILL);
  const auto killed = Clock::now();
  // The room goes on: both survivors decode new frames again...
  pump_all(survivors, 1500ms);  // frames in flight at the kill are not the room going on
  for (std::size_t i = 0; i < survivors.size(); ++i) frames_before[i] = survivors[i]->room_frames;
  bool going_on = false;
  while (Clock::now() - killed < 8s && !going_on) {
    pump_all(survivors, 50ms);
    going_on = true;
    for (std::size_t i = 0; i < survivors.size(); ++i)
      going_on = going_on && survivors[i]->room_frames >= frames_before[i] + 10;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - killed).count();
  std::cout << "room going on again " << seconds << " s after its owner was killed (new owner "
            << cluster.owner_of("meet") << ")" << std::endl;
  EXPECT_TRUE(going_on) << "the survivors decode no new frames";
  EXPECT_LT(seconds, 5.0) << "the room took over 5 s to go on";
  // ...and nobody was lost: no one left, the dead node's person keeps their seat.
  for (std::size_t i = 0; i < survivors.size(); ++i) {
    EXPECT_EQ(known_avatars(*survivors[i]), ids) << "a survivor lost a member";
    for (std::size_t p = left_before[i]; p < survivors[i]->presence.size(); ++p)
      EXPECT_NE(survivors[i]->presence[p].change, codec::Presence::Change::left)
          << "avatar " << survivors[i]->presence[p].avatar.id << " left";
  }
  EXPECT_NE(cluster.owner_of("meet"), owner);
  // The person whose node died comes back to another node with their resume key: same seat.
  RunningServer& other = cluster.node(dead == 0 ? 1 : 0);
  // They chose another language on the way back.
  auto back = join_node(other, "meet", "P" + std::to_string(dead), dead_resume, "", "de");
  ASSERT_TRUE(back->welcome.has_value());
  EXPECT_EQ(back->welcome->you, dead_id) << "the seat kept for them is theirs again";
  std::vector<RoomTestClient*> after = survivors;
  after.push_back(back.get());
  for (auto* c : after) c->frames_per_avatar.clear();
  EXPECT_TRUE(eventually(
      [&] {
        pump_all(after, 100ms);
        return everyone_sees(after, ids);
      },
      20s))
      << "after the takeover everyone sees everyone again";
  // Their lines are said in the language they came back with.
  back->send_message(codec::Chat{0, "wieder da"});
  RoomTestClient& listener = *survivors.front();
  EXPECT_TRUE(eventually(
      [&] {
        pump_all(after, 100ms);
        return !listener.speaking.empty() && listener.speaking.back().avatar == dead_id;
      },
      20s))
      << "the returning person's line was not said";
  if (!listener.speaking.empty()) {
    EXPECT_EQ(listener.speaking.back().language, "de");
  }
}

TEST(Cluster, RedisRestartsAndTheClusterRecovers) {
  Cluster cluster;
  cluster.add_node("a");
  cluster.add_node("b");
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  auto first = join_node(cluster.node(0), "meet", "First");
  const std::string owner = cluster.owner_of("meet");
  ASSERT_FALSE(owner.empty());
  RunningServer& owner_node = cluster.node(cluster.index_of(owner));
  RunningServer& other_node = cluster.node(1 - cluster.index_of(owner));
  // Someone bridged from the other node whichever node owns the room: the
  // one who must learn, once Redis is back, of whoever joined without it.
  auto bridged = join_node(other_node, "meet", "Bridged");
  ASSERT_TRUE(bridged->welcome.has_value());

  cluster.redis().stop();
  EXPECT_TRUE(eventually([&] { return !ready(owner_node.http_port()) && !ready(other_node.http_port()); }, 10s))
      << "nodes without Redis report not ready";
  EXPECT_EQ(http_get(owner_node.http_port(), "/readyz").body, "no Redis\n");
  // The owner keeps its room going for the people connected to it.
  auto local = join_node(owner_node, "meet", "Local");
  ASSERT_TRUE(local->welcome.has_value());
  const std::uint64_t frames = local->room_frames;
  local->pump_for(2s);
  EXPECT_GT(local->room_frames, frames + 10) << "the owner stopped its room without Redis";

  ASSERT_TRUE(cluster.redis().start()) << cluster.redis().error();
  EXPECT_TRUE(eventually([&] { return ready(owner_node.http_port()) && ready(other_node.http_port()); }, 15s))
      << "nodes are ready again once Redis is back";
  EXPECT_TRUE(eventually([&] { return cluster.owner_of("meet") == owner; }, 10s))
      << "the owner claims its room again in the new Redis";
  // Bridged across nodes again: a newcomer on the other node sees the owner's people.
  auto late = join_node(other_node, "meet", "Late");
  ASSERT_TRUE(late->welcome.has_value());
  std::set<std::uint32_t> people{first->welcome->you, bridged->welcome->you, local->welcome->you, late->welcome->you};
  std::vector<RoomTestClient*> all{first.get(), bridged.get(), local.get(), late.get()};
  EXPECT_TRUE(eventually(
      [&] {
        pump_all(all, 100ms);
        return everyone_sees(all, people);
      },
      30s))
      << "the cluster did not recover: " << unseen(all, people);
}

TEST(Cluster, ASlowSubscriberOnOneNodeDoesNotSlowTheRoomOnAnother) {
  Cluster cluster;
  cluster.add_node("a");
  cluster.add_node("b");
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  auto watcher = join_node(cluster.node(0), "pace", "Watcher");
  const std::string owner = cluster.owner_of("pace");
  ASSERT_FALSE(owner.empty());
  RunningServer& far = cluster.node(1 - cluster.index_of(owner));
  auto steady = join_node(far, "pace", "Steady");
  // A subscriber on the far node that reads nothing from now on, on a tiny buffer.
  auto slow = std::make_unique<RoomTestClient>(Transport::websocket, far.http_port());
  slow->shrink_receive_buffer(4096);
  slow->hello("pace", "Slow", "", 1'000'000);
  // Ticks the client's frames advance by per second of wall time, after
  // what was already waiting in its socket is read.
  auto tick_rate = [](RoomTestClient& c, std::chrono::milliseconds span) {
    c.pump_for(500ms);
    if (c.ticks.empty()) return 0.0;
    const std::uint32_t first = c.ticks.back().second;
    const auto start = Clock::now();
    c.pump_for(span);
    return (c.ticks.back().second - first) / std::chrono::duration<double>(Clock::now() - start).count();
  };

  watcher->pump_for(3s);
  steady->pump_for(1s);
  const double before = tick_rate(*watcher, 3000ms);
  // The slow one's node has its own queue for it; the room ticks on for the others.
  steady->pump_for(2s);
  const double during = tick_rate(*watcher, 4000ms);
  const double far_rate = tick_rate(*steady, 3000ms);
  std::cout << "room ticks seen on the owner's node: " << before << "/s before, " << during
            << "/s with a stuck subscriber on the other node; its neighbour there sees " << far_rate << "/s"
            << std::endl;
  EXPECT_GT(before, 20.0);
  EXPECT_GT(during, 0.8 * before) << "the stuck subscriber slowed the room on the owner's node";
  EXPECT_GT(far_rate, 0.8 * before) << "the stuck subscriber slowed its neighbour on its own node";
}

TEST(Cluster, ANewRoomGoesToTheLeastLoadedNode) {
  Cluster cluster;
  cluster.add_node("a");
  cluster.add_node("b");
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  // Node a carries people; b carries none (the lobby's three faces weigh a tenth each).
  std::vector<std::unique_ptr<RoomTestClient>> busy;
  for (int i = 0; i < 4; ++i) busy.push_back(join_node(cluster.node(0), "busy" + std::to_string(i), "P" + std::to_string(i)));
  std::this_thread::sleep_for(1500ms);  // loads reported at the next beats
  auto opener = join_node(cluster.node(0), "fresh", "Opener");
  ASSERT_TRUE(opener->welcome.has_value());
  EXPECT_EQ(cluster.owner_of("fresh"), "b") << "a new room opened on the busy node stayed there";
}

TEST(Cluster, RoomsOpenedTogetherSpreadOverTheNodes) {
  Cluster cluster;
  cluster.add_node("a");
  cluster.add_node("b");
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  std::this_thread::sleep_for(1200ms);  // both nodes have seen each other's load
  // Faster than the nodes report their loads: a placement counts at once.
  auto first = join_node(cluster.node(0), "one", "P1");
  auto second = join_node(cluster.node(0), "two", "P2");
  const std::string one = cluster.owner_of("one"), two = cluster.owner_of("two");
  EXPECT_FALSE(one.empty());
  EXPECT_NE(one, two) << "two rooms opened together went to the same node";
}

TEST(Cluster, AnAddresssConnectionsAreCountedAcrossNodes) {
  Cluster cluster;
  const std::string cap = kManyClientsFromOneAddress + " --max-connections-per-address 4";
  cluster.add_node("a", cap);
  cluster.add_node("b", cap);
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  std::vector<std::unique_ptr<RoomTestClient>> held;
  for (int i = 0; i < 3; ++i) held.push_back(join_node(cluster.node(0), "cap", "A" + std::to_string(i)));
  std::this_thread::sleep_for(1500ms);  // a beat or two: b hears what a holds
  auto fourth = join_node(cluster.node(1), "cap", "B0");
  EXPECT_TRUE(fourth->welcome.has_value()) << "the fourth connection from the address is within its share";
  std::this_thread::sleep_for(1500ms);
  auto fifth = std::make_unique<RoomTestClient>(Transport::websocket, cluster.node(1).http_port());
  const bool refused = !fifth->connected() || fifth->pump_until([&] { return fifth->closed(); }, 3s);
  EXPECT_TRUE(refused) << "a fifth connection from one address, on another node, was let in";
  // The share frees when connections close on the other node.
  held.clear();
  std::this_thread::sleep_for(2s);
  auto later = join_node(cluster.node(1), "cap", "B1");
  EXPECT_TRUE(later->welcome.has_value());
}

TEST(Cluster, AJoinTokenAdmitsOnePersonAcrossNodes) {
  Cluster cluster;
  const std::string secret = " --auth-secret s3cret" + kManyClientsFromOneAddress;
  cluster.add_node("a", secret);
  cluster.add_node("b", secret);
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  const auto now = std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  const std::string token = server::mint_join_token({"meet", "Ann", now + 600}, "s3cret");
  auto hello_with = [&](RunningServer& node, const std::string& resume) {
    auto client = std::make_unique<RoomTestClient>(Transport::websocket, node.http_port());
    codec::Hello hello;
    hello.room = "meet";
    hello.name = "Ann";
    hello.token = token;
    hello.resume = resume;
    client->send_message(hello);
    client->pump_until([&] { return client->welcome.has_value() || client->closed(); }, 10s);
    return client;
  };
  auto first = hello_with(cluster.node(0), "");
  ASSERT_TRUE(first->welcome.has_value());
  std::this_thread::sleep_for(1s);
  auto second = hello_with(cluster.node(1), "");
  EXPECT_FALSE(second->welcome.has_value()) << "one token admitted two people on two nodes";
  ASSERT_TRUE(second->closing.has_value());
  EXPECT_NE(second->closing->reason.find("in use"), std::string::npos) << second->closing->reason;
  // The same person, back on another node with their resume key, takes it over; the old link is told.
  auto back = hello_with(cluster.node(1), first->welcome->resume);
  EXPECT_TRUE(back->welcome.has_value()) << (back->closing ? back->closing->reason : "no answer");
  EXPECT_TRUE(first->pump_until([&] { return first->closing.has_value(); }, 5s));
  if (first->closing) {
    EXPECT_NE(first->closing->reason.find("replaced"), std::string::npos) << first->closing->reason;
  }
}

TEST(Cluster, AFaceUploadedToANodeThatDiesIsWornOnAnother) {
  Cluster cluster;
  cluster.add_node("a");
  cluster.add_node("b");
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  const auto photo = file_bytes(source_path("tests/data/grace_hopper.jpg"));
  const std::string body(photo.begin(), photo.end());
  // A photo's answer waits for its preparation (the landmark model loads first: seconds).
  const auto answer = http_exchange(cluster.node(0).http_port(),
                                    "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
                                    "Content-Type: image/jpeg\r\nContent-Length: " +
                                        std::to_string(body.size()) + "\r\n\r\n" + body,
                                    90);
  ASSERT_EQ(answer.status, 201) << answer.body;
  const auto uploaded = nlohmann::json::parse(answer.body, nullptr, false);
  const std::string asset = uploaded.value("asset", ""), key = uploaded.value("key", "");
  ASSERT_FALSE(asset.empty());
  const auto on_a = http_get(cluster.node(0).http_port(), "/api/packages/" + asset);
  ASSERT_EQ(on_a.status, 200);

  ::kill(cluster.node(0).process().pid(), SIGKILL);
  const auto on_b = http_get(cluster.node(1).http_port(), "/api/packages/" + asset);
  EXPECT_EQ(on_b.status, 200) << "the upload was lost with its node";
  EXPECT_TRUE(on_b.body == on_a.body) << "node b serves other bytes";
  // Its key, from node a, opens the face on node b: the cluster signs with one key.
  auto wearer = std::make_unique<RoomTestClient>(Transport::websocket, cluster.node(1).http_port());
  codec::Hello hello;
  hello.room = "meet";
  hello.name = "Grace";
  hello.avatar = asset;
  hello.avatar_key = key;
  wearer->send_message(hello);
  wearer->pump_until([&] { return wearer->welcome.has_value() || wearer->closed(); }, 15s);
  ASSERT_TRUE(wearer->welcome.has_value()) << (wearer->closing ? wearer->closing->reason : "no answer");
  bool wears = false;
  for (const auto& info : wearer->welcome->avatars) wears = wears || (info.id == wearer->welcome->you && info.asset == asset);
  EXPECT_TRUE(wears);
}

TEST(Cluster, AnAvatarDeletedOnOneNodeIsGoneFromEveryNodeAndItsWearerShownNeutral) {
  Cluster cluster;
  ASSERT_TRUE(two_ready_nodes(cluster));
  RunningServer& a = cluster.node(0);
  RunningServer& b = cluster.node(1);
  const auto package = server::make_demo_package(13);  // a face of its own: checked, not prepared
  const std::string body(package.begin(), package.end());
  const auto answer = http_exchange(a.http_port(),
                                    "POST /api/avatars HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
                                    "Content-Type: application/x-facewire-avatar\r\nContent-Length: " +
                                        std::to_string(body.size()) + "\r\n\r\n" + body,
                                    30);
  ASSERT_EQ(answer.status, 201) << answer.body;
  const auto uploaded = nlohmann::json::parse(answer.body, nullptr, false);
  const std::string asset = uploaded.value("asset", ""), key = uploaded.value("key", "");
  ASSERT_FALSE(asset.empty());

  // Ann wears it on node b (which fetches it from Redis); Bo watches from node a.
  auto ann = std::make_unique<RoomTestClient>(Transport::websocket, b.http_port(), "127.0.4.1");
  codec::Hello hello;
  hello.room = "meet";
  hello.name = "Ann";
  hello.avatar = asset;
  hello.avatar_key = key;
  ann->send_message(hello);
  ASSERT_TRUE(ann->pump_until([&] { return ann->welcome.has_value() || ann->closed(); }, 15s));
  ASSERT_TRUE(ann->welcome.has_value()) << (ann->closing ? ann->closing->reason : "no answer");
  const std::uint32_t ann_id = ann->welcome->you;
  ASSERT_TRUE(std::filesystem::exists(b.data() / "avatars" / (asset + ".fwa"))) << "node b keeps a copy";
  auto bo = join(a, Transport::websocket, "meet", "Bo");
  ASSERT_TRUE(bo->welcome.has_value()) << (bo->closing ? bo->closing->reason : "no answer");
  const auto full = std::make_pair(ann_id, static_cast<int>(codec::PackageChunk::Quality::full));
  ASSERT_TRUE(bo->pump_until([&] { return bo->packages[full].complete(); }, 15s));
  EXPECT_EQ(bo->packages[full].bytes, package);

  const auto deleted = http_exchange(a.http_port(), "DELETE /api/avatars/" + asset +
                                                        " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
                                                        "X-Avatar-Key: " + key + "\r\n\r\n");
  ASSERT_EQ(deleted.status, 204) << deleted.body;

  // Gone from Redis, and from node b's own store, which was told.
  server::RedisBlocking redis(cluster.redis_address(), 2000ms);
  const auto copy = redis.command({"EXISTS", "fw:avatar:" + asset});
  ASSERT_TRUE(copy);
  EXPECT_EQ(copy->integer, 0) << "Redis still holds the avatar";
  const auto marked = redis.command({"SISMEMBER", "fw:avatars:deleted", asset});
  ASSERT_TRUE(marked);
  EXPECT_EQ(marked->integer, 1);
  EXPECT_TRUE(eventually([&] { return !std::filesystem::exists(b.data() / "avatars" / (asset + ".fwa")); }, 5s))
      << "node b kept its copy";
  EXPECT_EQ(http_get(b.http_port(), "/api/packages/" + asset).status, 404);

  // Bo sees Ann under the procedural face of her name.
  auto plain_ann = join(b, Transport::websocket, "elsewhere", "Ann");
  ASSERT_TRUE(plain_ann->welcome.has_value());
  const auto procedural = http_get(b.http_port(), "/api/packages/" + plain_ann->welcome->avatars.back().asset);
  ASSERT_EQ(procedural.status, 200);
  EXPECT_TRUE(bo->pump_until(
      [&] {
        const auto& p = bo->packages[full];
        return p.complete() && std::string(p.bytes.begin(), p.bytes.end()) == procedural.body;
      },
      10s))
      << "Bo, on another node, still sees the deleted face";
  EXPECT_TRUE(bo->errors.empty()) << bo->errors.front();
}


/// How many action units of `avatar`'s face, as `client` decodes it now, are
/// near their full intensity: a face the room's behavior never makes has
/// them all so (the forged one below).
std::size_t full_action_units(const RoomTestClient& client, std::uint32_t avatar) {
  const codec::Decoder* decoder = client.decoder.avatar(avatar);
  if (!decoder) return 0;
  const codec::FaceParams face = decoder->face();
  std::size_t full = 0;
  for (const float au : face.au) full += au >= 0.95f;
  return full;
}

// An attacker who can publish on the cluster's Redis channels, and is not a
// node holding a room's lease (nor a node at all), tries what one forged
// line could do before: block an address on every node for good, throw
// every bridged person out with an empty roster, and put a face on someone.
TEST(Cluster, MessagesForgedIntoRedisChangeNothingAClientSees) {
  Cluster cluster;
  const std::string flags = kManyClientsFromOneAddress + " --max-connections-per-address 4";
  cluster.add_node("a", flags);
  cluster.add_node("b", flags);
  for (std::size_t i = 0; i < 2; ++i) ASSERT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s));
  auto first = join_node(cluster.node(0), "forge", "First", "", "127.0.1.10");
  const std::string owner = cluster.owner_of("forge");
  ASSERT_FALSE(owner.empty());
  RunningServer& bridging = cluster.node(1 - cluster.index_of(owner));
  auto bridged = join_node(bridging, "forge", "Bridged", "", "127.0.2.10");
  ASSERT_TRUE(first->welcome && bridged->welcome);
  const std::uint32_t first_id = first->welcome->you, bridged_id = bridged->welcome->you;
  std::vector<RoomTestClient*> both{first.get(), bridged.get()};
  ASSERT_TRUE(eventually([&] { pump_all(both, 100ms); return everyone_sees(both, {first_id, bridged_id}); }, 30s));
  const auto members_before = known_avatars(*bridged);
  const long refused_before = test::refusal_count(bridging.http_port(), "cluster_message");

  server::RedisBlocking attacker(cluster.redis_address(), 2000ms);
  auto publish = [&](const std::string& channel, const std::string& payload) {
    const auto reply = attacker.command({"PUBLISH", channel, payload});
    ASSERT_TRUE(reply && reply->type == server::RedisReply::Type::integer) << "PUBLISH to " << channel;
  };
  auto down = [&](server::bridge::Down message) {
    const auto bytes = server::bridge::encode(message);
    publish("fw:room:forge:down", std::string(bytes.begin(), bytes.end()));
  };
  // 1. An address blocked on every node: a node that is none says it holds
  // a thousand connections from it.
  for (int i = 0; i < 3; ++i) publish("fw:limits", "node mallory\nbeat\nc 1000 127.0.3.7\n");
  // 2. Faces: every action unit at full intensity on both people, for a
  // second of ticks, and one tick of faces that are not numbers at all.
  codec::FaceParams mask;
  mask.au.fill(1.f);
  mask.head_yaw_rad = 1.2f;
  codec::FaceParams broken;
  broken.au.fill(std::numeric_limits<float>::quiet_NaN());
  broken.head_pitch_rad = std::numeric_limits<float>::infinity();
  std::size_t forged_faces_seen = 0;
  for (std::uint32_t tick = 0; tick < 30; ++tick) {
    down({.kind = server::bridge::DownKind::tick, .owner = "mallory", .tick = 1'000'000 + tick,
          .faces = {{first_id, tick == 15 ? broken : mask}, {bridged_id, mask}}});
    bridged->pump_for(30ms);
    forged_faces_seen += full_action_units(*bridged, first_id) >= 20;
  }
  // 3. An empty roster: everyone bridged is told the room moved.
  server::bridge::Down roster{.kind = server::bridge::DownKind::roster, .owner = "mallory"};
  codec::write_message(codec::Attention{}, roster.attention);
  down(roster);
  // 4. Bytes that are no chat line, as chat.
  down({.kind = server::bridge::DownKind::chat, .owner = "mallory", .message = {0x80 | 3, 0xff, 0xff, 0xff, 0xff}});

  pump_all(both, 1500ms);
  const long refused = test::refusal_count(bridging.http_port(), "cluster_message") - refused_before;
  auto victim = std::make_unique<RoomTestClient>(Transport::websocket, bridging.http_port(), "127.0.3.7");
  const bool victim_in = victim->connected() && !victim->pump_until([&] { return victim->closed(); }, 1500ms);
  std::cout << "forged into Redis: 127.0.3.7 " << (victim_in ? "connects" : "is refused") << "; the bridged person "
            << (bridged->closing ? "was disconnected (" + bridged->closing->reason + ")" : std::string("stays"))
            << "; forged faces decoded in " << forged_faces_seen << " of 30 ticks; " << refused
            << " messages refused as cluster_message" << std::endl;
  EXPECT_TRUE(victim_in) << "a forged limits line blocked an address";
  EXPECT_FALSE(bridged->closing.has_value()) << "a forged roster disconnected a bridged person: " << bridged->closing->reason;
  EXPECT_EQ(known_avatars(*bridged), members_before) << "a forged roster changed whom the bridged person sees";
  EXPECT_EQ(forged_faces_seen, 0u) << "forged faces reached a client";
  EXPECT_EQ(full_action_units(*bridged, first_id), 0u) << "a forged face stuck";
  EXPECT_TRUE(bridged->errors.empty()) << bridged->errors.front();
  EXPECT_TRUE(first->errors.empty()) << first->errors.front();
  // 3 limits lines, 30 ticks, the roster and the chat line; more would be
  // the owner's own news refused.
  EXPECT_EQ(refused, 35) << "forged messages not counted in /metrics, or the owner's news refused";
  // The room goes on for both, as before.
  for (auto* c : both) c->frames_per_avatar.clear();
  EXPECT_TRUE(eventually([&] { pump_all(both, 100ms); return everyone_sees(both, {first_id, bridged_id}); }, 10s));
}


TEST(Cluster, FaceLabPreviewsOnTwoNodesKeepNothingInRedis) {
  // Each node numbers its previews from 1, so two nodes both hold a
  // "~lab-1": a preview must stay on its node, or their members and states
  // would meet under one name in Redis, and a node taking over rooms after
  // another died would restore somebody's private preview as a room.
  Cluster cluster;
  auto& a = cluster.add_node("a");
  auto& b = cluster.add_node("b");
  ASSERT_TRUE(eventually([&] { return ready(a.http_port()) && ready(b.http_port()); }, 15s));
  std::vector<std::unique_ptr<RoomTestClient>> labs;
  for (RunningServer* node : {&a, &b}) {
    auto lab = std::make_unique<RoomTestClient>(Transport::websocket, node->http_port());
    codec::Hello hello;
    hello.room = "lab";
    hello.name = "Lab";
    hello.preview = true;
    lab->send_message(hello);
    ASSERT_TRUE(lab->pump_until([&] { return lab->welcome.has_value() || lab->closed(); }, 15s));
    ASSERT_TRUE(lab->welcome.has_value()) << (lab->closing ? lab->closing->reason : "no closing");
    labs.push_back(std::move(lab));
  }
  EXPECT_EQ(labs[0]->welcome->room, labs[1]->welcome->room) << "the test means two previews of one name";
  // Rooms keep their state once a second: wait for a few.
  std::vector<RoomTestClient*> both{labs[0].get(), labs[1].get()};
  pump_all(both, 2500ms);
  server::RedisBlocking redis(cluster.redis_address(), 2000ms);
  const auto keys = redis.command({"KEYS", "*~lab*"});
  ASSERT_TRUE(keys && !keys->is_error());
  std::string found;
  for (const auto& key : keys->elements) found += key.text + " ";
  EXPECT_TRUE(keys->elements.empty()) << "previews wrote to Redis: " << found;
  for (auto* lab : both) EXPECT_FALSE(lab->closed()) << "a preview ended: " << lab->closing->reason;
}

// Saved looks are the cluster's (PROTOCOL.md 8.2): saved on the node that
// owns the room, listed and played from the other, whose person is bridged
// to it, and gone from every node and from Redis with their avatar.
TEST(Cluster, ALookSavedOnOneNodePlaysOnAnotherAndGoesWithItsAvatar) {
  Cluster cluster;
  ASSERT_TRUE(two_ready_nodes(cluster));
  auto bo = join_node(cluster.node(0), "looks", "Bo", "", "127.0.5.1");
  const std::string owner = cluster.owner_of("looks");
  ASSERT_FALSE(owner.empty());
  RunningServer& saving = cluster.node(cluster.index_of(owner));
  RunningServer& bridging = cluster.node(1 - cluster.index_of(owner));
  const test::OwnedAvatar ann = test::upload_own_face("127.0.4.1", saving.http_port(), 21);
  ASSERT_FALSE(ann.key.empty());
  ASSERT_EQ(test::save_look("127.0.4.1", saving.http_port(), ann, "flushed", test::kBlushLook).status, 200);
  const std::string smile = "ClearAllFrame\nBeginKeyFrame\n  12 2.0\nAnimate 5 \"smile\"\nend\n";
  ASSERT_EQ(test::save_look("127.0.4.1", bridging.http_port(), ann, "smile", smile).status, 200);
  const auto listed = test::look_request("127.0.4.1", bridging.http_port(), "GET", ann.asset, "", ann.key);
  ASSERT_EQ(listed.status, 200);
  EXPECT_EQ(nlohmann::json::parse(listed.body)["looks"].size(), 2u) << listed.body;
  const auto copy = bridging.data() / "avatars" / (ann.asset + ".looks");
  EXPECT_TRUE(std::filesystem::exists(copy));

  auto ann_in = test::wear_in(bridging.tcp_port(), "127.0.4.1", "looks", "Ann", ann);
  ASSERT_TRUE(bo->welcome && ann_in->welcome) << (ann_in->closing ? ann_in->closing->reason : "no answer");
  const std::uint32_t ann_id = ann_in->welcome->you;
  ASSERT_TRUE(bo->pump_until([&] { return bo->decoder.avatar(ann_id) != nullptr; }, 15s)) << "Bo never saw Ann";
  bo->pump_for(1000ms);
  const float before = test::largest_blush(*bo, ann_id);
  const auto played = test::play_look(*ann_in, 1, "flushed");
  ASSERT_TRUE(played);
  EXPECT_EQ(*played, "");
  EXPECT_GT(test::blush_within(*bo, ann_id, before + 0.1f, 10s), before + 0.1f)
      << "the look saved on " << owner << ", played through the bridge, did not redden Ann for Bo";

  const auto deleted = http_exchange(saving.http_port(), "DELETE /api/avatars/" + ann.asset +
                                                             " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n"
                                                             "X-Avatar-Key: " + ann.key + "\r\n\r\n");
  ASSERT_EQ(deleted.status, 204);
  server::RedisBlocking redis(cluster.redis_address(), 2000ms);
  const auto in_redis = redis.command({"EXISTS", "fw:avatar:" + ann.asset + ":looks"});
  ASSERT_TRUE(in_redis);
  EXPECT_EQ(in_redis->integer, 0) << "Redis kept the looks of a deleted avatar";
  EXPECT_TRUE(eventually([&] { return !std::filesystem::exists(copy); }, 10s)) << "the other node kept its copy";
  EXPECT_EQ(test::look_request("127.0.4.1", bridging.http_port(), "GET", ann.asset, "", ann.key).status, 404);
}

// While Redis is away a node keeps saved looks on its own disk (and says
// so in its log); when Redis comes back without them, the node shares its
// copy again, and the other node lists them.
TEST(Cluster, LooksSavedWhileRedisIsAwayAreKeptAndSharedWhenItIsBack) {
  Cluster cluster;
  ASSERT_TRUE(two_ready_nodes(cluster));
  RunningServer& a = cluster.node(0);
  RunningServer& b = cluster.node(1);
  const long refused_before = test::refusal_count(b.http_port(), "cluster_message");
  const test::OwnedAvatar ann = test::upload_own_face("127.0.4.1", a.http_port(), 22);
  ASSERT_FALSE(ann.key.empty());
  ASSERT_EQ(test::save_look("127.0.4.1", a.http_port(), ann, "flushed", test::kBlushLook).status, 200);

  // Twice a second the nodes share what addresses spent: once at least before Redis goes.
  std::this_thread::sleep_for(1500ms);
  cluster.redis().stop();
  const std::string smile = "ClearAllFrame\nBeginKeyFrame\n  12 2.0\nAnimate 5 \"smile\"\nend\n";
  EXPECT_EQ(test::save_look("127.0.4.1", a.http_port(), ann, "smile", smile).status, 200);
  const auto here = test::look_request("127.0.4.1", a.http_port(), "GET", ann.asset, "", ann.key);
  ASSERT_EQ(here.status, 200);
  EXPECT_EQ(nlohmann::json::parse(here.body)["looks"].size(), 2u) << "node a without Redis: " << here.body;

  // The node's blocking connection tries Redis again at most once a second:
  // calls that failed just now would keep it from sharing its copies at
  // once when Redis is back (it shares them as it reconnects).
  std::this_thread::sleep_for(1500ms);
  ASSERT_TRUE(cluster.redis().start()) << cluster.redis().error();
  EXPECT_TRUE(eventually([&] { return ready(a.http_port()) && ready(b.http_port()); }, 15s));
  std::string listed;
  EXPECT_TRUE(eventually(
      [&] {
        const auto reply = test::look_request("127.0.4.1", b.http_port(), "GET", ann.asset, "", ann.key);
        listed = reply.body;
        const auto looks = nlohmann::json::parse(reply.body, nullptr, false);
        return reply.status == 200 && looks.is_object() && looks["looks"].size() == 2;
      },
      20s))
      << "node b did not list the looks node a kept while Redis was away: " << listed;
  // The changes' rates took nothing the other node's limits news refuses.
  EXPECT_EQ(test::refusal_count(b.http_port(), "cluster_message"), refused_before);
}

}  // namespace
}  // namespace fw::test
