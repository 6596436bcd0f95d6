// A person's AU definitions in the room simulation (redefined_units.hpp):
// taken whole or refused with a reason, versioned, measured with the
// redefined morph on the redefining face alone, forgotten when it leaves.
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "redefinition_budget.hpp"
#include "room_simulation.hpp"
#include "test_paths.hpp"

namespace fw::server {
namespace {

std::string au1_example() {
  std::ifstream in(test::source_path("avatar/behavior/script/examples/au1.fws"));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

const std::size_t kAu1Left = static_cast<std::size_t>(codec::au_channel(1, codec::AuSide::left));
const std::size_t kAu1Right = static_cast<std::size_t>(codec::au_channel(1, codec::AuSide::right));

// Inner brows up at full strength, held a while.
constexpr const char* kRaiseAu1 = "ClearAllFrame BeginKeyFrame 1 2.0 Animate 20 \"Texture\" end";

TEST(RedefinedUnits, ADefinitionRedefinesTheSendersUnitAloneWithAVersion) {
  RoomSimulation room(RoomSimulationOptions{});
  const AvatarId a = room.add_avatar({"a", true});
  const AvatarId b = room.add_avatar({"b", true});
  EXPECT_FALSE(room.unit_morphs(a));
  ASSERT_EQ(room.command(a, FacsCommand{au1_example()}), "");
  const auto morphs = room.unit_morphs(a);
  ASSERT_TRUE(morphs);
  EXPECT_EQ(morphs->avatar, a);
  EXPECT_EQ(morphs->version, 1u);
  ASSERT_EQ(morphs->units.size(), 2u);
  EXPECT_EQ(morphs->units[0].channel, kAu1Left);
  EXPECT_EQ(morphs->units[1].channel, kAu1Right);
  // The paper's indices name points from the viewer's left: on this face
  // they all lie on the person's right, so the left channel moves nothing.
  EXPECT_TRUE(morphs->units[0].moves.empty());
  EXPECT_FALSE(morphs->units[1].moves.empty());
  EXPECT_FALSE(room.unit_morphs(b));
  // Restoring is a change too: a new version with no units.
  ASSERT_EQ(room.command(a, FacsCommand{"AU 1 end"}), "");
  ASSERT_TRUE(room.unit_morphs(a));
  EXPECT_EQ(room.unit_morphs(a)->version, 2u);
  EXPECT_TRUE(room.unit_morphs(a)->units.empty());
}

TEST(RedefinedUnits, AnAvatarHoldsAFewRedefinedUnitsAndAScriptIsTakenWhole) {
  RoomSimulation room(RoomSimulationOptions{});
  const AvatarId a = room.add_avatar({"a", true});
  ASSERT_EQ(room.command(a, FacsCommand{"AU 1 brow 0 0 5 0 end AU 2 brow 1 0 5 0 end AU 4 brow 2 0 -5 0 end"}), "");
  ASSERT_EQ(room.command(a, FacsCommand{"AU 9 nose 0 0 3 0 end"}), "");
  const std::string refused = room.command(a, FacsCommand{"AU 12 mouth_corner_left 0 3 3 0 end"});
  EXPECT_NE(refused.find("would have 5 redefined action units; at most 4 at once: restore one first"),
            std::string::npos) << refused;
  EXPECT_EQ(room.unit_morphs(a)->version, 2u);  // nothing of the refused script was taken
  // Restoring one and defining another in one script fits.
  EXPECT_EQ(room.command(a, FacsCommand{"AU 9 end AU 12 mouth_corner_left 0 3 3 0 end"}), "");
  EXPECT_EQ(room.unit_morphs(a)->version, 3u);
  // A script whose sentence is refused takes none of its definitions either.
  std::string long_sentence = "AU 1 end ClearAllFrame BeginKeyFrame 12 2.0 Animate 700 end";
  EXPECT_NE(room.command(a, FacsCommand{long_sentence}), "");
  EXPECT_EQ(room.unit_morphs(a)->version, 3u);
}

TEST(RedefinedUnits, TheRedefiningFaceIsMeasuredWithItsMorphOthersWithTheShippedUnit) {
  RoomSimulationOptions options;
  options.seed = 5;
  RoomSimulation room(options);
  const AvatarId a = room.add_avatar({"a", true});
  const AvatarId b = room.add_avatar({"b", true});
  ASSERT_EQ(room.command(a, FacsCommand{au1_example()}), "");
  ASSERT_EQ(room.command(a, FacsCommand{kRaiseAu1}), "");
  ASSERT_EQ(room.command(b, FacsCommand{kRaiseAu1}), "");
  for (int i = 0; i < 70; ++i) room.tick();  // the 2 s rise, into the hold
  // The physics face does not make the redefined unit; the measurement
  // finds it from its morph (measured against the shipped basis it would be
  // near 0: nothing in the tissue moves that way).
  EXPECT_GT(room.face(a).au[kAu1Right], 0.8f);
  // Its left channel moves nothing now, so nothing measures it.
  EXPECT_LT(room.face(a).au[kAu1Left], 0.05f);
  // The other face raises its brows with the physics face's shipped AU 1.
  EXPECT_GT(room.face(b).au[kAu1Left], 0.5f);
  EXPECT_EQ(room.physics_faces(), 2u);
}

TEST(RedefinedUnits, ASetKeptByAFormerOwnerIsRestoredAtItsVersionAndMeasuredWith) {
  RoomSimulation owner(RoomSimulationOptions{});
  const AvatarId a = owner.add_avatar({"a", true});
  ASSERT_EQ(owner.command(a, FacsCommand{au1_example()}), "");
  ASSERT_EQ(owner.command(a, FacsCommand{"AU 9 nose 0 0 3 0 end"}), "");
  const codec::UnitMorphs kept = *owner.unit_morphs(a);
  ASSERT_EQ(kept.version, 2u);

  // Another server takes the room over: the avatar under its id, its set given back.
  RoomSimulation successor(RoomSimulationOptions{});
  ASSERT_TRUE(successor.restore_avatar(a, {"a", true}));
  EXPECT_EQ(successor.restore_unit_morphs(a, kept), "");
  ASSERT_TRUE(successor.unit_morphs(a));
  EXPECT_EQ(successor.unit_morphs(a)->version, 2u) << "the clients hold version 2 already";
  EXPECT_EQ(successor.unit_morphs(a)->units, kept.units) << "the set as the former owner measured with";
  // The face is measured with the restored morph, as on the former owner.
  ASSERT_EQ(successor.command(a, FacsCommand{kRaiseAu1}), "");
  for (int i = 0; i < 70; ++i) successor.tick();
  EXPECT_GT(successor.face(a).au[kAu1Right], 0.8f);
  // The next change is newer than what every client holds.
  ASSERT_EQ(successor.command(a, FacsCommand{"AU 9 end"}), "");
  EXPECT_EQ(successor.unit_morphs(a)->version, 3u);

  // What no redefinition makes is refused, and the avatar keeps what it had.
  codec::UnitMorphs five = kept;
  five.units.clear();
  std::set<int> aus;  // one channel each of the first five action units
  for (std::size_t c = 0; c < codec::kAuChannelCount && aus.size() < 5; ++c)
    if (aus.insert(codec::kAuChannels[c].au).second) five.units.push_back({static_cast<std::uint8_t>(c), {}});
  EXPECT_NE(successor.restore_unit_morphs(a, five), "");
  codec::UnitMorphs past_face = kept;
  past_face.units = {{static_cast<std::uint8_t>(kAu1Right), {{1000, {1, 1, 1}}}}};
  EXPECT_NE(successor.restore_unit_morphs(a, past_face).find("vertex 1000"), std::string::npos);
  EXPECT_EQ(successor.unit_morphs(a)->version, 3u);
  EXPECT_NE(successor.restore_unit_morphs(a + 1, kept), "") << "no such avatar";
}

TEST(RedefinedUnits, ARedefinitionIsForgottenWhenItsAvatarLeaves) {
  RoomSimulationOptions options;
  options.id_space = 3;
  options.id_quiet_ticks = 0;
  RoomSimulation room(options);
  const AvatarId a = room.add_avatar({"a", true});
  ASSERT_NE(room.add_avatar({"b", true}), 0u);  // holds the other id
  ASSERT_EQ(room.command(a, FacsCommand{au1_example()}), "");
  room.remove_avatar(a);
  EXPECT_FALSE(room.unit_morphs(a));
  room.tick();
  const AvatarId again = room.add_avatar({"c", true});
  ASSERT_EQ(again, a);  // the id handed out again carries nothing of the last one
  EXPECT_FALSE(room.unit_morphs(again));
}

}  // namespace
}  // namespace fw::server

namespace fw::server {
namespace {

// The room's people together, on however many addresses, may make every
// client receive only so many bytes of unit morphs a second.
TEST(RedefinitionBudget, ABurstThenItsRateAndTheWaitNamed) {
  RedefinitionBudget budget;
  EXPECT_FALSE(budget.take(16 * 1024, 0.0)) << "one largest set at once";
  const auto wait = budget.take(1000, 1.0);  // 200 bytes back after a second
  ASSERT_TRUE(wait);
  EXPECT_NEAR(*wait, 4.0, 1e-9) << "800 bytes short at 200 a second";
  EXPECT_FALSE(budget.take(1000, 5.0));
}

TEST(RedefinedUnits, ARoomsRedefinitionsAreHeldToItsByteRateWhoeverSendsThem) {
  RoomSimulationOptions options;
  options.physics = false;  // a minute of ticks, which only the room's clock needs
  RoomSimulation room(options);
  std::vector<AvatarId> people;
  for (const char* name : {"a", "b", "c", "d", "e", "f", "g", "h"}) people.push_back(room.add_avatar({name, true}));
  // Each person redefines, then restores, their unit (each set a few hundred
  // bytes), as fast as the script rate lets them: no tick in between.
  int refused = 0;
  std::string reason;
  for (int round = 0; round < 200 && refused == 0; ++round)
    for (const AvatarId p : people) {
      const std::string result = room.command(p, FacsCommand{round % 2 ? "AU 1 end" : au1_example()});
      if (!result.empty()) ++refused, reason = result;
    }
  EXPECT_GT(refused, 0) << "past the burst, the room's redefinitions wait";
  EXPECT_NE(reason.find("try again in"), std::string::npos) << reason;
  // A minute later the budget has come back.
  for (int i = 0; i < 60 * 30; ++i) room.tick();
  EXPECT_EQ(room.command(people[0], FacsCommand{au1_example()}), "");
}

}  // namespace
}  // namespace fw::server
