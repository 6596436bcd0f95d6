// Redefined action units across the nodes of a cluster (PROTOCOL.md 5.17,
// server/CLUSTER.md), on a real redis-server and real nodes: a person on the
// room's owner redefines a unit and a person on another node receives the
// set (and so does a newcomer there), and decodes a face that departs from
// the shipped unit; a person bridged from another node redefines their own
// (the script goes up, the set comes down to both nodes); the owner is
// killed, and the node that takes the room over still gives every newcomer
// (and the person whose node died, coming back to their seat) the sets, at
// their versions, the next change one newer.
#include <csignal>
#include <memory>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "cluster_fixture.hpp"
#include "fw/model/avatar_model.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/unit_morphs.hpp"
#include "sample_messages.hpp"

namespace fw::test {
namespace {

// AU 12 drawn as brows and forehead far up: nothing like the shipped smile
// (the room page's test of redefined units uses the same).
constexpr const char* kBrowsForAu12 =
    "AU 12\n"
    "Above_Brow 6 0 40 0\nAbove_Brow 7 0 40 0\n"
    "Brow 3 0 40 0\nBrow 4 0 40 0\nBrow 5 0 40 0\nBrow 6 0 40 0\nBrow 7 0 40 0\nBrow 8 0 40 0\n"
    "end";
// AU 12 at its full strength over 2 s, held 1.5 s.
constexpr const char* kSmile = "ClearAllFrame BeginKeyFrame 12 2.0 Animate 20 \"Texture\" end";
constexpr const char* kNoseForAu9 = "AU 9 nose 0 0 3 0 end";

/// The newest set `client` holds for `avatar`, or null.
const codec::UnitMorphs* set_of(const RoomTestClient& client, std::uint32_t avatar) {
  const codec::UnitMorphs* newest = nullptr;
  for (const auto& set : client.unit_morphs)
    if (set.avatar == avatar && (!newest || set.version > newest->version)) newest = &set;
  return newest;
}

/// How far (model units, the largest vertex) the generic face rebuilt from
/// `face` with the units of `set` lies from the same face with the shipped
/// units: what a client draws differently once it holds the set.
float departure(const codec::FaceParams& face, const codec::UnitMorphs& set) {
  const model::AvatarModel shipped = model::generic_avatar_model();
  model::AvatarModel redefined = shipped;
  std::string error;
  const auto units = model::unit_morph_set(set, model::generic_face().skin.positions.size(), error);
  EXPECT_TRUE(units) << error;
  if (!units) return 0;
  model::set_unit_morphs(redefined, model::generic_face(), *units);
  const auto a = model::reconstruct_face(shipped, face).positions;
  const auto b = model::reconstruct_face(redefined, face).positions;
  float largest = 0;
  for (std::size_t v = 0; v < a.size() && v < b.size(); ++v) largest = std::max(largest, glm::length(a[v] - b[v]));
  return largest;
}

/// Two nodes, and who owns `room` (opened by a first person on node a).
struct TwoNodes {
  Cluster cluster;
  std::unique_ptr<RoomTestClient> opener;
  RunningServer* owner = nullptr;
  RunningServer* other = nullptr;
  std::string owner_name, other_name;

  explicit TwoNodes(const std::string& room) {
    cluster.add_node("a");
    cluster.add_node("b");
    for (std::size_t i = 0; i < 2; ++i)
      EXPECT_TRUE(eventually([&] { return ready(cluster.node(i).http_port()); }, 20s)) << "node " << i << " not ready";
    opener = join_node(cluster.node(0), room, "Opener");
    owner_name = cluster.owner_of(room);
    const std::size_t owner_index = cluster.index_of(owner_name);
    EXPECT_LT(owner_index, 2u) << "room " << room << " has no owner among the nodes";
    owner = &cluster.node(owner_index < 2 ? owner_index : 0);
    other = &cluster.node(owner_index == 0 ? 1 : 0);
    other_name = owner_index == 0 ? "b" : "a";
  }
};

TEST(ClusterUnitMorphs, ARedefinitionOnTheOwnersNodeReachesAnotherNodeAndItsNewcomers) {
  TwoNodes nodes("units");
  auto ann = join_node(*nodes.owner, "units", "Ann");
  auto bob = join_node(*nodes.other, "units", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  const std::uint32_t id = ann->welcome->you;
  std::vector<RoomTestClient*> all{ann.get(), bob.get(), nodes.opener.get()};
  pump_all(all, 500ms);
  EXPECT_TRUE(bob->unit_morphs.empty()) << "nobody redefined anything yet";

  ann->send_message(facs_command(1, kBrowsForAu12));
  ann->send_message(facs_command(2, kSmile));
  ASSERT_TRUE(eventually(
      [&] {
        pump_all(all, 50ms);
        return set_of(*bob, id) && set_of(*ann, id) && ann->results.size() == 2;
      },
      15s))
      << "Bob, on the node that bridges the room, never received Ann's set";
  EXPECT_EQ(ann->results[0].error, "");
  EXPECT_EQ(ann->results[1].error, "");
  const codec::UnitMorphs sent = *set_of(*ann, id);
  EXPECT_EQ(sent.version, 1u);
  EXPECT_FALSE(sent.units.empty());
  EXPECT_EQ(set_of(*bob, id)->version, 1u);
  EXPECT_EQ(set_of(*bob, id)->units, sent.units) << "the set as the owner measures with";
  EXPECT_EQ(bob->unit_morphs.size(), 1u) << "told once";

  // The face Bob decodes, rebuilt with the set, is not the shipped unit's.
  float largest = 0;
  eventually(
      [&] {
        pump_all(all, 50ms);
        if (const codec::Decoder* face = bob->decoder.avatar(id)) largest = std::max(largest, departure(face->face(), sent));
        return largest > 0.05f;
      },
      6s);
  std::cout << "Ann's smile as Bob decodes it, drawn with her set, departs from the shipped one by " << largest
            << " model units" << std::endl;
  EXPECT_GT(largest, 0.05f) << "Bob's decoded face of Ann does not move by the redefined unit";

  // A newcomer on the bridging node hears of the set after its welcome.
  auto carl = join_node(*nodes.other, "units", "Carl");
  ASSERT_TRUE(carl->welcome);
  ASSERT_TRUE(carl->pump_until([&] { return set_of(*carl, id) != nullptr; }, 10s)) << "Carl never received Ann's set";
  EXPECT_EQ(set_of(*carl, id)->units, sent.units);
  EXPECT_TRUE(carl->errors.empty()) << carl->errors.front();

  // A restore reaches the other node as a new version with no units.
  ann->send_message(facs_command(3, "AU 12 end"));
  all.push_back(carl.get());
  ASSERT_TRUE(eventually(
      [&] {
        pump_all(all, 50ms);
        return set_of(*bob, id)->version == 2 && set_of(*carl, id)->version == 2;
      },
      10s));
  EXPECT_TRUE(set_of(*bob, id)->units.empty());
  EXPECT_TRUE(bob->errors.empty()) << bob->errors.front();
}

TEST(ClusterUnitMorphs, APersonBridgedFromAnotherNodeRedefinesTheirOwnUnit) {
  TwoNodes nodes("far");
  auto ann = join_node(*nodes.owner, "far", "Ann");
  auto bob = join_node(*nodes.other, "far", "Bob");
  auto dora = join_node(*nodes.other, "far", "Dora");
  ASSERT_TRUE(ann->welcome && bob->welcome && dora->welcome);
  const std::uint32_t id = bob->welcome->you;
  std::vector<RoomTestClient*> all{ann.get(), bob.get(), dora.get(), nodes.opener.get()};
  bob->send_message(facs_command(7, kNoseForAu9));
  // The script goes up to the owner; its set comes down to both nodes.
  ASSERT_TRUE(eventually(
      [&] {
        pump_all(all, 50ms);
        return set_of(*ann, id) && set_of(*bob, id) && set_of(*dora, id) && !bob->results.empty();
      },
      15s))
      << "the set of a person bridged from " << nodes.other_name << " did not reach everyone";
  EXPECT_EQ(bob->results.front().request_id, 7u);
  EXPECT_EQ(bob->results.front().error, "");
  EXPECT_EQ(set_of(*ann, id)->version, 1u);
  EXPECT_EQ(set_of(*bob, id)->units, set_of(*ann, id)->units);
  EXPECT_EQ(set_of(*dora, id)->units, set_of(*ann, id)->units);
  EXPECT_EQ(set_of(*ann, ann->welcome->you), nullptr) << "Ann redefined nothing";
}

TEST(ClusterUnitMorphs, TheNodeThatTakesTheRoomOverKeepsTheSetsAndTheirVersions) {
  TwoNodes nodes("heir");
  auto ann = join_node(*nodes.owner, "heir", "Ann");
  auto bob = join_node(*nodes.other, "heir", "Bob");
  ASSERT_TRUE(ann->welcome && bob->welcome);
  const std::uint32_t ann_id = ann->welcome->you, bob_id = bob->welcome->you;
  std::vector<RoomTestClient*> all{ann.get(), bob.get()};
  ann->send_message(facs_command(1, kBrowsForAu12));
  bob->send_message(facs_command(2, kNoseForAu9));
  ASSERT_TRUE(eventually(
      [&] {
        pump_all(all, 50ms);
        return set_of(*bob, ann_id) && set_of(*bob, bob_id) && set_of(*ann, bob_id);
      },
      15s));
  const codec::UnitMorphs anns = *set_of(*bob, ann_id), bobs = *set_of(*bob, bob_id);
  pump_all(all, 1500ms);  // the records the owner keeps are in Redis

  ::kill(nodes.owner->process().pid(), SIGKILL);
  ASSERT_TRUE(eventually([&] { return nodes.cluster.owner_of("heir") == nodes.other_name; }, 10s))
      << "node " << nodes.other_name << " did not take the room over";
  // A newcomer on the new owner: Ann's seat is kept for her (her node died),
  // and both sets come after the welcome, at the versions everyone holds.
  auto carl = join_node(*nodes.other, "heir", "Carl");
  ASSERT_TRUE(carl->welcome);
  ASSERT_TRUE(carl->pump_until([&] { return set_of(*carl, ann_id) && set_of(*carl, bob_id); }, 10s))
      << "the node that took the room over forgot its redefinitions";
  EXPECT_EQ(set_of(*carl, ann_id)->version, anns.version);
  EXPECT_EQ(set_of(*carl, ann_id)->units, anns.units);
  EXPECT_EQ(set_of(*carl, bob_id)->version, bobs.version);
  EXPECT_EQ(set_of(*carl, bob_id)->units, bobs.units);
  // Ann comes back (her seat was kept) and hears of both sets after her welcome, her own too.
  auto back = join_node(*nodes.other, "heir", "Ann", ann->welcome->resume);
  ASSERT_TRUE(back->welcome);
  EXPECT_EQ(back->welcome->you, ann_id);
  ASSERT_TRUE(back->pump_until([&] { return set_of(*back, ann_id) && set_of(*back, bob_id); }, 10s));
  EXPECT_EQ(set_of(*back, ann_id)->units, anns.units);
  // The next change is newer than what the clients hold, so they take it.
  bob->send_message(facs_command(3, "AU 9 end"));
  std::vector<RoomTestClient*> survivors{bob.get(), carl.get()};
  ASSERT_TRUE(eventually(
      [&] {
        pump_all(survivors, 50ms);
        return set_of(*carl, bob_id)->version == bobs.version + 1 && set_of(*bob, bob_id)->version == bobs.version + 1;
      },
      10s))
      << "a change after the takeover did not come as a newer version";
  EXPECT_TRUE(set_of(*carl, bob_id)->units.empty());
  EXPECT_TRUE(carl->errors.empty()) << carl->errors.front();
}

}  // namespace
}  // namespace fw::test
