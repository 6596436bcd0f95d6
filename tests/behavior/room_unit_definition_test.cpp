// AU definitions in a room (room_script.hpp): made into morphs of the generic
// face, split over a unit's sides, and held to a room's bounds with reasons.
#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "fw/behavior/au_definition_morph.hpp"
#include "fw/behavior/room_script.hpp"
#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"
#include "test_paths.hpp"

namespace fw::behavior {
namespace {

std::string unit_example(const std::string& name) {
  std::ifstream in(test::source_path("avatar/behavior/script/examples/" + name));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string unit_refusal(std::string_view text) {
  RoomScript read;
  return read_room_script(text, read);
}

std::size_t channel(int au, codec::AuSide side) { return static_cast<std::size_t>(codec::au_channel(au, side)); }

TEST(RoomUnitDefinition, TheExampleRedefinesBothSidesOfAu1AsItsMorph) {
  RoomScript read;
  ASSERT_EQ(read_room_script(unit_example("au1.fws"), read), "");
  ASSERT_EQ(read.units.size(), 1u);
  const UnitDefinition& unit = read.units.front();
  EXPECT_EQ(unit.au, 1);
  EXPECT_FALSE(unit.restore);
  ASSERT_EQ(unit.morphs.size(), 2u);
  const model::Morph& left = unit.morphs.at(channel(1, codec::AuSide::left));
  const model::Morph& right = unit.morphs.at(channel(1, codec::AuSide::right));
  // The two sides add up to the definition's morph, each on its own side.
  const script::ScriptResult parsed = script::parse_script(script::default_language(), unit_example("au1.fws"));
  std::string error;
  const auto whole = au_definition_morph(parsed.meaning.au_definitions.front(), model::generic_face(), error);
  ASSERT_TRUE(whole) << error;
  const auto& positions = model::generic_face().skin.positions;
  float lifted = 0;
  for (std::size_t v = 0; v < positions.size(); ++v) {
    EXPECT_LT(glm::length(left.vertex_delta[v] + right.vertex_delta[v] - whole->vertex_delta[v]), 1e-6f);
    if (positions[v].x < -1e-3f) {
      EXPECT_EQ(left.vertex_delta[v], glm::vec3(0.0f)) << v;
    }
    if (positions[v].x > 1e-3f) {
      EXPECT_EQ(right.vertex_delta[v], glm::vec3(0.0f)) << v;
    }
    lifted = std::max(lifted, whole->vertex_delta[v].y);
  }
  EXPECT_GT(lifted, 0.05f);  // the brows rise
  // The preview is not played in a room, but the sentence beside it would be.
  EXPECT_FALSE(read.animation);
}

TEST(RoomUnitDefinition, ADefinitionWithoutDisplacementsRestoresTheShippedUnit) {
  RoomScript read;
  ASSERT_EQ(read_room_script("AU 12 end", read), "");
  ASSERT_EQ(read.units.size(), 1u);
  EXPECT_TRUE(read.units.front().restore);
  EXPECT_TRUE(read.units.front().morphs.empty());
}

TEST(RoomUnitDefinition, AMidlineUnitHasOneChannel) {
  RoomScript read;
  ASSERT_EQ(read_room_script("AU 9 nose 0 0 5 0 end", read), "");
  ASSERT_EQ(read.units.front().morphs.size(), 1u);
  EXPECT_TRUE(read.units.front().morphs.contains(channel(9, codec::AuSide::both)));
}

TEST(RoomUnitDefinition, TheRoomsBoundsRefuseWithReasons) {
  // More definitions than a script may hold.
  std::string five;
  for (const int au : {1, 2, 4, 5, 6}) five += "AU " + std::to_string(au) + " brow 0 0 5 0 end\n";
  EXPECT_NE(unit_refusal(five).find("5 AU definitions; at most 4 are taken at once"), std::string::npos) << unit_refusal(five);
  // A unit FaceParams does not stream.
  const std::string uncarried = unit_refusal("AU 11 nose 0 0 5 0 end");
  EXPECT_NE(uncarried.find("AU 11 is not one of the units a face streams (1, 2, 4"), std::string::npos) << uncarried;
  EXPECT_EQ(uncarried.rfind("script 1:1: ", 0), 0u) << uncarried;
  // Too far.
  const std::string far = unit_refusal("AU 1 brow 0 0 41 0 end");
  EXPECT_NE(far.find("moves brow 0 by 41; at most 40 along each axis"), std::string::npos) << far;
  EXPECT_EQ(unit_refusal("AU 1 brow 0 0 40 0 end"), "");
  // Too many control points (distinct ones: the parser refuses a point given twice).
  std::string distinct = "AU 1\n";
  std::size_t written = 0;
  for (const std::string region : {"forehead", "hairline", "cheek_left", "cheek_right", "nose", "chin"})
    for (std::size_t p = 0; p < region_control_points(model::generic_face(), {region}).size() && written < 65; ++p, ++written)
      distinct += region + " " + std::to_string(p) + " 0 1 0\n";
  ASSERT_EQ(written, 65u);
  distinct += "end";
  const std::string crowded = unit_refusal(distinct);
  EXPECT_NE(crowded.find("moves 65 control points; at most 64"), std::string::npos) << crowded;
  // A control point the region does not have.
  const std::string missing = unit_refusal("AU 1 brow 999 0 5 0 end");
  EXPECT_NE(missing.find("AU 1: region brow has control points 0.."), std::string::npos) << missing;
}

}  // namespace
}  // namespace fw::behavior
