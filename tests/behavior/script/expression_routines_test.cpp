#include "fw/script/expression_routines.hpp"

#include <utility>

#include <gtest/gtest.h>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using test::errors_of;
using test::joined;
using test::warnings_of;

const Language& expression_language() {
  static const Language language = [] {
    std::vector<GrammarError> errors;
    RoutineLibrary library;
    add_expression_routines(library);
    auto loaded = load_language(*builtin_grammar("expression.grammar"), {}, library, errors);
    EXPECT_TRUE(loaded) << joined(errors);
    return std::move(*loaded);
  }();
  return language;
}

ScriptResult parse_expression(std::string_view text) { return parse_script(expression_language(), text); }

// The "done when": the paper's anger sentence gives the keyframes it describes.
TEST(ExpressionRoutines, ThePapersAngerSentence) {
  const ScriptResult result = parse_expression(test::read_source("avatar/behavior/script/examples/anger.fws"));
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  ASSERT_EQ(result.meaning.animations.size(), 1u);
  const KeyframeAnimation& anger = result.meaning.animations[0];
  EXPECT_TRUE(anger.clear_frames);
  ASSERT_EQ(anger.keyframes.size(), 2u);
  EXPECT_TRUE(anger.keyframes[0].aus.empty()) << "the first BeginKeyFrame is the neutral face";
  const std::vector<std::pair<int, double>> paper = {{2, 1.0},  {4, 2.0},  {5, 1.2},  {7, 1.0},  {15, 1.2},
                                                     {17, 1.2}, {20, 0.8}, {23, 0.3}, {26, 0.4}, {42, 1.0}};
  const std::vector<AuIntensity>& aus = anger.keyframes[1].aus;
  ASSERT_EQ(aus.size(), paper.size());
  for (std::size_t i = 0; i < paper.size(); ++i) {
    EXPECT_EQ(aus[i].au, paper[i].first);
    EXPECT_DOUBLE_EQ(aus[i].intensity, paper[i].second) << "AU " << aus[i].au;
    EXPECT_DOUBLE_EQ(aus[i].face_intensity, paper[i].second / 2) << "AU " << aus[i].au << ": 2 is the full strength";
    EXPECT_EQ(aus[i].carried, aus[i].au != 42);
  }
  ASSERT_EQ(anger.plays.size(), 2u);
  EXPECT_EQ(anger.plays[0].kind, PlayKind::animate);
  EXPECT_EQ(anger.plays[0].steps, 2);
  EXPECT_EQ(anger.plays[0].shading, "SmoothShading");
  EXPECT_EQ(anger.plays[1].shading, "Texture");
  EXPECT_EQ(anger.plays[1].keyframe_count, 2u);
  const auto warnings = warnings_of(result);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].position, (SourcePosition{16, 2}));
  EXPECT_NE(warnings[0].message.find("AU 42 (slit)"), std::string::npos) << warnings[0].message;
}

TEST(ExpressionRoutines, KeepAllFrameContinuesAndIntegersAreStrengthsToo) {
  const ScriptResult result = parse_expression("KeepAllFrame BeginKeyFrame 12 1 end");
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_FALSE(result.meaning.animations[0].clear_frames);
  EXPECT_DOUBLE_EQ(result.meaning.animations[0].keyframes[0].aus[0].intensity, 1.0);
}

TEST(ExpressionRoutines, ActionUnitsOutsideFacsAreErrors) {
  const auto errors = errors_of(parse_expression("ClearAllFrame BeginKeyFrame 3 1.0 40 0.5 end"));
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].message, "AU 3 is not a FACS action unit (FACS numbers are 1-2, 4-39, 41-46, 51-58 and 61-66)");
  EXPECT_EQ(errors[0].position, (SourcePosition{1, 29}));
  EXPECT_EQ(errors[1].position, (SourcePosition{1, 35}));
}

TEST(ExpressionRoutines, IntensitiesAreBounded) {
  const auto errors = errors_of(parse_expression("ClearAllFrame BeginKeyFrame 4 2.5 12 -0.5 end"));
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].message.find("the intensity 2.5 of AU 4 is out of range: write 0 to 2"), std::string::npos)
      << errors[0].message;
  EXPECT_EQ(errors[0].position, (SourcePosition{1, 31}));
  EXPECT_TRUE(parse_expression("ClearAllFrame BeginKeyFrame 4 2.0 12 0 end").ok());
}

TEST(ExpressionRoutines, AnActionUnitOncePerKeyframe) {
  const auto errors = errors_of(parse_expression("ClearAllFrame BeginKeyFrame 4 1.0 4 0.5 BeginKeyFrame 4 0.2 end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "AU 4 appears twice in this keyframe (first at 1:29); give it once");
}

TEST(ExpressionRoutines, StepsAndShadingAreChecked) {
  auto errors = errors_of(parse_expression("ClearAllFrame Animate 0 \"Texture\" end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "the number of steps must be 1 to 10000, not 0");
  errors = errors_of(parse_expression("ClearAllFrame Animate 2 \"\" end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("the shading must be 1 to 64 characters"), std::string::npos);
}

TEST(ExpressionRoutines, TooManyKeyframesIsAnError) {
  std::string text = "ClearAllFrame";
  for (std::size_t i = 0; i <= kMaxKeyframes; ++i) text += " BeginKeyFrame";
  const auto errors = errors_of(parse_expression(text + " end"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("more than 1000 keyframes"), std::string::npos);
}

TEST(ExpressionRoutines, RoutinesBoundInTheWrongPlaceTellTheDesigner) {
  std::vector<GrammarError> grammar_errors;
  RoutineLibrary library;
  add_expression_routines(library);
  const auto language = load_language(
      {"wrong.grammar", "#Terminal\nk\nend\n#Production\n<S> ::= <K> end => end_animation\n<K> ::= k => begin_keyframe\n#End\n"},
      {}, library, grammar_errors);
  ASSERT_TRUE(language) << joined(grammar_errors);
  const auto errors = errors_of(parse_script(*language, "k end"));
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].message.find("the routine begin_keyframe ran outside an expression sentence"), std::string::npos)
      << errors[0].message;
}

}  // namespace
}  // namespace fw::script
