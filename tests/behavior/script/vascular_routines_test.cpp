#include "fw/script/vascular_routines.hpp"

#include <gtest/gtest.h>

#include "fw/script/grammar_sources.hpp"
#include "fw/script/parser.hpp"
#include "fw/script/region_names.hpp"
#include "test_support.hpp"

namespace fw::script {
namespace {

using codec::ColourRegion;
using test::errors_of;
using test::joined;
using test::warnings_of;

const Language& vascular_language() {
  static const Language language = [] {
    std::vector<GrammarError> errors;
    RoutineLibrary library;
    add_vascular_routines(library);
    auto loaded = load_language(*builtin_grammar("vascular.grammar"), {}, library, errors);
    EXPECT_TRUE(loaded) << joined(errors);
    return std::move(*loaded);
  }();
  return language;
}

ScriptResult parse_vascular(std::string_view text) { return parse_script(vascular_language(), text); }

double channel(const ColourChannels& c, ColourRegion region) { return c[static_cast<std::size_t>(region)]; }

// The paper's example (section 5, Figure 4): four stages of 10, 10, 60 and
// 20 percent, and blush1 as the paper defines it.
TEST(VascularRoutines, ThePapersBlushingEpisode) {
  const ScriptResult result = parse_vascular(R"(
[emotion blushing
  [stage1 duration 10 [expression blush1 intensity 0.9]]
  [stage2 duration 10 [expression blush2 intensity 0.8]]
  [stage3 duration 60 [expression blush3 intensity 0.6]]
  [stage4 duration 20]]
[expression blush1 [mpca forehead intensity 0.4] [mpca cheeks intensity 0.6] [mpca ears intensity 0.2]]
)");
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  ASSERT_EQ(result.meaning.emotions.size(), 1u);
  const VascularEmotion& blushing = result.meaning.emotions[0];
  EXPECT_EQ(blushing.name, "blushing");
  ASSERT_EQ(blushing.stages.size(), 4u);
  const double starts[] = {0, 10, 20, 80}, ends[] = {10, 20, 80, 100};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(blushing.stages[i].start_percent, starts[i]);
    EXPECT_DOUBLE_EQ(blushing.stages[i].end_percent, ends[i]);
  }
  EXPECT_EQ(blushing.stages[0].expression, "blush1");
  EXPECT_DOUBLE_EQ(blushing.stages[0].intensity, 0.9);
  EXPECT_TRUE(blushing.stages[3].expression.empty());
  // The envelope of Figure 4: up to 0.9, down through 0.8 and 0.6, released.
  ASSERT_EQ(blushing.envelope.size(), 5u);
  const double levels[] = {0, 0.9, 0.8, 0.6, 0};
  for (std::size_t i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(blushing.envelope[i].intensity, levels[i]);
  EXPECT_DOUBLE_EQ(blushing.envelope[4].at_percent, 100);

  // blush2 and blush3 are not defined: colours stay unresolved, with warnings.
  EXPECT_FALSE(blushing.colours_resolved);
  EXPECT_TRUE(blushing.colour_keys.empty());
  const auto warnings = warnings_of(result);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].position, (SourcePosition{4, 4}));
  EXPECT_NE(warnings[0].message.find("'blush2', which this script does not define"), std::string::npos);

  ASSERT_EQ(result.meaning.vascular_expressions.size(), 1u);
  const VascularExpression& blush1 = result.meaning.vascular_expressions[0];
  EXPECT_DOUBLE_EQ(channel(blush1.channels, ColourRegion::forehead), 0.4);
  EXPECT_DOUBLE_EQ(channel(blush1.channels, ColourRegion::cheek_left), 0.6);
  EXPECT_DOUBLE_EQ(channel(blush1.channels, ColourRegion::cheek_right), 0.6);
  EXPECT_DOUBLE_EQ(channel(blush1.channels, ColourRegion::sides), 0.2);
  EXPECT_DOUBLE_EQ(channel(blush1.channels, ColourRegion::nose), 0.0);
  EXPECT_EQ(blush1.regions[1].channels, (std::vector<std::string>{"cheek_left", "cheek_right"}));
}

TEST(VascularRoutines, ColourKeysScaleEachExpressionByItsStage) {
  const ScriptResult result = parse_vascular(test::read_source("avatar/behavior/script/examples/blushing.fws"));
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  EXPECT_TRUE(result.diagnostics.empty()) << joined(result.diagnostics);
  const VascularEmotion& blushing = result.meaning.emotions.at(0);
  ASSERT_TRUE(blushing.colours_resolved);
  ASSERT_EQ(blushing.colour_keys.size(), 5u);
  EXPECT_EQ(blushing.colour_keys[0].channels, ColourChannels{});
  EXPECT_DOUBLE_EQ(channel(blushing.colour_keys[1].channels, ColourRegion::forehead), 0.36);  // 0.4 x 0.9
  EXPECT_DOUBLE_EQ(channel(blushing.colour_keys[1].channels, ColourRegion::cheek_left), 0.54);
  // blush3: head 0.3 everywhere, cheeks 0.7 (the stronger wins), at 0.6.
  EXPECT_DOUBLE_EQ(channel(blushing.colour_keys[3].channels, ColourRegion::nose), 0.18);
  EXPECT_DOUBLE_EQ(channel(blushing.colour_keys[3].channels, ColourRegion::cheek_right), 0.42);
  EXPECT_DOUBLE_EQ(blushing.colour_keys[3].at_percent, 80);
  EXPECT_EQ(blushing.colour_keys[4].channels, ColourChannels{});
}

TEST(VascularRoutines, DurationsArePercentagesThatAddUpTo100) {
  auto errors = errors_of(parse_vascular("[emotion shy [s1 duration 50%] [s2 duration 40]]"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].position, (SourcePosition{1, 10}));
  EXPECT_EQ(errors[0].message,
            "the stages of emotion 'shy' last 90 percent in all; durations are percentages of the episode and must add up to 100");
  errors = errors_of(parse_vascular("[emotion shy [s1 duration 0] [s2 duration 100]]"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("the duration 0 is out of range"), std::string::npos);
  EXPECT_TRUE(parse_vascular("[emotion shy [s1 duration 50%] [s2 duration 50.0%]]").ok());
  errors = errors_of(parse_vascular("[emotion empty]"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("has no stages"), std::string::npos);
}

TEST(VascularRoutines, RegionsAndIntensitiesAreChecked) {
  const auto errors = errors_of(parse_vascular("[expression e [mpca knees intensity 0.5] [mpca nose intensity 1.5] "
                                      "[mpca Nose intensity 0.1] [mpca nose intensity 0.2]]"));
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_NE(errors[0].message.find("unknown colour region 'knees'; regions are forehead, cheek_left"),
            std::string::npos)
      << errors[0].message;
  EXPECT_EQ(errors[1].message, "the intensity 1.5 is out of range: write 0 to 1");
  EXPECT_NE(errors[2].message.find("region 'nose' already has an intensity at 1:"), std::string::npos)
      << errors[2].message;
}

TEST(VascularRoutines, NamesAreDefinedOnce) {
  auto errors = errors_of(parse_vascular("[expression e] [expression e]"));
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("expression 'e' is already defined at 1:13"), std::string::npos) << errors[0].message;
  errors = errors_of(parse_vascular("[emotion a [s duration 100]] [emotion a [s duration 100]]"));
  ASSERT_EQ(errors.size(), 1u);
  errors = errors_of(parse_vascular("[emotion a [s duration 50] [s duration 50]]"));
  ASSERT_EQ(errors.size(), 2u) << "the twin stage, and so the durations";
  EXPECT_NE(errors[0].message.find("already has a stage 's'"), std::string::npos);
}

TEST(VascularRoutines, PallorIsAChannelToo) {
  const ScriptResult result =
      parse_vascular("[emotion shock [s1 duration 30 [expression pale intensity 1]] [s2 duration 70 [expression pale intensity 0.5]]]\n"
            "[expression pale [mpca pallor intensity 0.8]]");
  ASSERT_TRUE(result.ok()) << joined(result.diagnostics);
  const VascularEmotion& shock = result.meaning.emotions.at(0);
  ASSERT_TRUE(shock.colours_resolved);
  EXPECT_DOUBLE_EQ(shock.colour_keys[1].channels[kPallorChannel], 0.8);
  EXPECT_DOUBLE_EQ(shock.colour_keys[2].channels[kPallorChannel], 0.4);
}

}  // namespace
}  // namespace fw::script
