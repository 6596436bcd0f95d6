#include "fw/script/script_builder.hpp"

#include <gtest/gtest.h>

namespace fw::script {
namespace {

TEST(ScriptBuilder, ADiscardedSentenceLeavesNoTrace) {
  ScriptBuilder builder;
  builder.begin_sentence();
  builder.meaning.animations.emplace_back();
  builder.begin_sentence();  // the first sentence was fine
  builder.meaning.animations.emplace_back();
  builder.meaning.emotions.emplace_back();
  builder.au_definition.emplace();
  builder.discard_sentence();
  EXPECT_EQ(builder.meaning.animations.size(), 1u);
  EXPECT_TRUE(builder.meaning.emotions.empty());
  EXPECT_FALSE(builder.au_definition);
}

TEST(ScriptBuilder, BeginningASentenceForgetsWhatWasLeftOpen) {
  ScriptBuilder builder;
  builder.animation.emplace();
  builder.vascular_expression.emplace();
  builder.begin_sentence();
  EXPECT_FALSE(builder.animation);
  EXPECT_FALSE(builder.vascular_expression);
}

TEST(ScriptBuilder, SaysWhichRoutineShouldHaveClosedTheSentence) {
  ScriptBuilder builder;
  EXPECT_EQ(builder.unfinished(), "");
  builder.emotion.emplace();
  EXPECT_NE(builder.unfinished().find("end_emotion"), std::string::npos) << builder.unfinished();
}

}  // namespace
}  // namespace fw::script
