#include "fw/behavior/au_definition_morph.hpp"

#include <gtest/gtest.h>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"

namespace fw::behavior {
namespace {

// The AU 1 definition as printed in the syntax-directed paper.
constexpr const char* kAu1 = R"(AU 1
Above_Brow      6  0.00 10.00 0.00
Above_Brow      7  0.00 10.00 0.00
Brow            3  0.00 10.00 0.00
Brow            4  0.00 10.00 0.00
Brow            5  0.00 20.00 0.00
Brow            6  0.00 20.00 0.00
Brow            7  0.00 10.00 0.00
Brow            8  0.00 10.00 0.00
Below_Lower_Lid 0  0.00  5.00 0.00
Below_Lower_Lid 3  2.00  8.00 0.00
Below_Lower_Lid 5  1.00  7.00 0.00
Below_Lower_Lid 10 -1.00  7.00 0.00
Below_Lower_Lid 12 -2.00  8.00 0.00
Below_Lower_Lid 15  0.00  5.00 0.00
true
Animate 4 "SmoothShading"
end
)";

script::AuDefinition parse_definition(const std::string& text) {
  const script::ScriptResult result = script::parse_script(script::default_language(), text);
  EXPECT_EQ(result.meaning.au_definitions.size(), 1u);
  return result.meaning.au_definitions.empty() ? script::AuDefinition{} : result.meaning.au_definitions.front();
}

// The paper numbers the control points of its own 1986-vertex face, so its
// indices name other points here; what carries over is the mechanism.
TEST(AuDefinitionMorph, ThePapersAu1MovesOnlyTheRegionsItNames) {
  const model::GenericFace& face = model::generic_face();
  std::string error;
  const auto morph = au_definition_morph(parse_definition(kAu1), face, error);
  ASSERT_TRUE(morph.has_value()) << error;
  int moved_up = 0;
  for (std::size_t v = 0; v < face.skin.positions.size(); ++v) {
    const glm::vec3 d = morph->vertex_delta[v];
    EXPECT_GE(d.y, 0.0f) << "every displacement in the definition points up";
    moved_up += d.y > 0.0f;
  }
  EXPECT_GT(moved_up, 10);
  for (int mouth = 48; mouth < 68; ++mouth)
    EXPECT_EQ(morph->vertex_delta[face.landmark_vertices[static_cast<std::size_t>(mouth)]], glm::vec3(0.0f)) << mouth;
}

TEST(AuDefinitionMorph, AControlPointMovesByItsDisplacement) {
  const model::GenericFace& face = model::generic_face();
  std::string error;
  const auto morph = au_definition_morph(parse_definition("AU 1\nBrow 3 0.00 10.00 0.00\ntrue\nend\n"), face, error, 0.01f);
  ASSERT_TRUE(morph.has_value()) << error;
  const std::uint32_t point = region_control_points(face, {"brow_right", "brow_left"})[3];
  EXPECT_NEAR(morph->vertex_delta[point].y, 0.1f, 1e-5f);
  EXPECT_NEAR(morph->vertex_delta[point].x, 0.0f, 1e-6f);
}

TEST(AuDefinitionMorph, ControlPointsRunAcrossTheFace) {
  const model::GenericFace& face = model::generic_face();
  const auto points = region_control_points(face, {"brow_right", "brow_left"});
  ASSERT_GE(points.size(), 10u);
  for (std::size_t i = 1; i < points.size(); ++i)
    EXPECT_LE(face.skin.positions[points[i - 1]].x, face.skin.positions[points[i]].x);
}

TEST(AuDefinitionMorph, AMissingControlPointIsNamed) {
  std::string error;
  const auto morph = au_definition_morph(parse_definition("AU 1\nBrow 999 0 1 0\ntrue\nend\n"), model::generic_face(), error);
  EXPECT_FALSE(morph.has_value());
  EXPECT_NE(error.find("point 999 does not exist"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::behavior
