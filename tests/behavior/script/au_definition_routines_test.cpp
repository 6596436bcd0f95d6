#include "fw/script/au_definition_routines.hpp"

#include <gtest/gtest.h>

#include "fw/script/expression_routines.hpp"
#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using test::errors_of;
using test::joined;

const Language& au_language() {
  static const Language language = [] {
    std::vector<GrammarError> errors;
    RoutineLibrary library;
    add_expression_routines(library);  // animate, for the previews
    add_au_definition_routines(library);
    auto loaded = load_language(*builtin_grammar("au_definition.grammar"), {}, library, errors);
    EXPECT_TRUE(loaded) << joined(errors);
    return std::move(*loaded);
  }();
  return language;
}

ScriptResult parse_au(std::string_view text) { return parse_script(au_language(), text); }

// The "done when": the paper's AU 1 definition.
TEST(AuDefinitionRoutines, ThePapersAu1) {
  const ScriptResult result = parse_au(test::read_source("avatar/behavior/script/examples/au1.fws"));
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_TRUE(result.diagnostics.empty()) << joined(result.diagnostics);
  ASSERT_EQ(result.meaning.au_definitions.size(), 1u);
  const AuDefinition& au1 = result.meaning.au_definitions[0];
  EXPECT_EQ(au1.au, 1);
  EXPECT_TRUE(au1.carried);
  EXPECT_TRUE(au1.preview_from_neutral);
  struct Row {
    const char* region;
    int point;
    double dx, dy;
  };
  const Row paper[] = {{"Above_Brow", 6, 0, 10},      {"Above_Brow", 7, 0, 10},      {"Brow", 3, 0, 10},
                       {"Brow", 4, 0, 10},            {"Brow", 5, 0, 20},            {"Brow", 6, 0, 20},
                       {"Brow", 7, 0, 10},            {"Brow", 8, 0, 10},            {"Below_Lower_Lid", 0, 0, 5},
                       {"Below_Lower_Lid", 3, 2, 8},  {"Below_Lower_Lid", 5, 1, 7},  {"Below_Lower_Lid", 10, -1, 7},
                       {"Below_Lower_Lid", 12, -2, 8}, {"Below_Lower_Lid", 15, 0, 5}};
  ASSERT_EQ(au1.displacements.size(), std::size(paper));
  for (std::size_t i = 0; i < std::size(paper); ++i) {
    const ControlPointDisplacement& d = au1.displacements[i];
    EXPECT_EQ(d.region, paper[i].region);
    EXPECT_EQ(d.point, paper[i].point);
    EXPECT_DOUBLE_EQ(d.displacement[0], paper[i].dx) << i;
    EXPECT_DOUBLE_EQ(d.displacement[1], paper[i].dy) << i;
    EXPECT_DOUBLE_EQ(d.displacement[2], 0.0) << i;
  }
  EXPECT_EQ(au1.displacements[0].face_regions, std::vector<std::string>{"forehead"});
  EXPECT_EQ(au1.displacements[2].face_regions, (std::vector<std::string>{"brow_right", "brow_left"}));
  ASSERT_EQ(au1.previews.size(), 2u);
  EXPECT_EQ(au1.previews[0].steps, 4);
  EXPECT_EQ(au1.previews[0].shading, "SmoothShading");
  EXPECT_EQ(au1.previews[1].shading, "Texture");
}

TEST(AuDefinitionRoutines, FalseStartsFromTheCurrentFramesAndTheFlagIsOptional) {
  ScriptResult result = parse_au("AU 12 cheek_left 0 1 2 3 false end");
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_FALSE(result.meaning.au_definitions[0].preview_from_neutral);
  result = parse_au("AU 12 cheek_left 0 1 2 3 end");
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_TRUE(result.meaning.au_definitions[0].preview_from_neutral);
}

TEST(AuDefinitionRoutines, BadRegionsPointsAndDisplacementsAreErrors) {
  const auto errors = errors_of(parse_au("AU 1\nAbve_Brow 6 0 10 0\nBrow -1 0 2000 0\nend"));
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].position, (SourcePosition{2, 1}));
  EXPECT_NE(errors[0].message.find("unknown region 'Abve_Brow'; regions are the generic face's forehead"),
            std::string::npos)
      << errors[0].message;
  EXPECT_EQ(errors[1].message, "control point -1 is out of range: write 0 to 9999");
  EXPECT_EQ(errors[2].position, (SourcePosition{3, 11}));
}

TEST(AuDefinitionRoutines, EachControlPointOnceAndEachActionUnitOnce) {
  auto errors = errors_of(parse_au("AU 1 Brow 3 0 1 0 brow 3 0 2 0 end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "control point 3 of brow already moves at 1:6; give it once");
  errors = errors_of(parse_au("AU 1 Brow 3 0 1 0 end\nAU 1 Brow 4 0 1 0 end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "AU 1 is already defined at 1:1; keep one definition per script");
}

TEST(AuDefinitionRoutines, ActionUnitsFacesDoNotCarryAreKeptWithAWarning) {
  const ScriptResult result = parse_au("AU 43 upper_lid 2 0 -5 0 end\nAU 3 nose 0 0 1 0 end");
  ASSERT_EQ(result.meaning.au_definitions.size(), 1u);
  EXPECT_FALSE(result.meaning.au_definitions[0].carried);
  ASSERT_EQ(test::warnings_of(result).size(), 1u);
  EXPECT_NE(test::warnings_of(result)[0].message.find("AU 43 (eyes closed)"), std::string::npos);
  ASSERT_EQ(errors_of(result).size(), 1u);
  EXPECT_NE(errors_of(result)[0].message.find("AU 3 is not a FACS action unit"), std::string::npos);
}

}  // namespace
}  // namespace fw::script
