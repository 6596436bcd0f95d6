#include "fw/behavior/room_script.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "test_paths.hpp"

namespace fw::behavior {
namespace {

std::string example(const std::string& name) {
  std::ifstream in(test::source_path("avatar/behavior/script/examples/" + name));
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string refusal(std::string_view text) {
  RoomScript read;
  return read_room_script(text, read);
}

TEST(RoomScript, AnExpressionSentenceOrAVascularEmotionIsPlayed) {
  RoomScript read;
  ASSERT_EQ(read_room_script(example("anger.fws"), read), "");
  EXPECT_TRUE(read.animation && !read.emotion);
  ASSERT_EQ(read_room_script(example("blushing.fws"), read), "");
  ASSERT_TRUE(read.emotion && !read.animation);
  EXPECT_EQ(read.emotion->name, "blushing");
  EXPECT_TRUE(read.emotion->colours_resolved);
  ASSERT_EQ(read_room_script("KeepAllFrame BeginKeyFrame 12 1.0 Animate 3 \"Texture\" end\n" + example("blushing.fws"), read), "");
  EXPECT_TRUE(read.animation && read.emotion) << "one of each together";
}

TEST(RoomScript, AScriptErrorIsAnsweredWithItsLineAndColumn) {
  const std::string error = refusal("ClearAllFrame\nBeginKeyFrame\n  12 strong\nend");
  EXPECT_EQ(error.rfind("script 3:6: expected", 0), 0u) << error;
  EXPECT_NE(error.find("found the name 'strong'"), std::string::npos) << error;
  EXPECT_EQ(refusal("ClearAllFrame BeginKeyFrame 12 2.5 end").rfind("script 1:32: the intensity 2.5", 0), 0u);
}

TEST(RoomScript, OverSizeIsRefusedWithTheLimit) {
  const std::string comment = "# " + std::string(kMaxRoomScriptBytes, 'x') + "\n";
  const std::string error = refusal(comment + "ClearAllFrame BeginKeyFrame 12 1.0 Animate 3 \"Texture\" end");
  EXPECT_NE(error.find("bytes; at most 4096"), std::string::npos) << error;
}

TEST(RoomScript, OverLongSentencesAreRefusedWithTheLimit) {
  std::string error = refusal("ClearAllFrame BeginKeyFrame 12 1.0 Animate 300 \"Texture\" Animate 301 \"Texture\" end");
  EXPECT_NE(error.find("plays 60 s"), std::string::npos) << error;
  EXPECT_NE(error.find("at most 60 s"), std::string::npos) << error;
  EXPECT_EQ(refusal("ClearAllFrame BeginKeyFrame 12 1.0 Animate 300 \"Texture\" Animate 300 \"Texture\" end"), "") << "a minute is allowed";
  std::string many = "ClearAllFrame";
  for (std::size_t k = 0; k <= kMaxRoomScriptKeyframes; ++k) many += " BeginKeyFrame 12 1.0";
  error = refusal(many + " Animate 5 \"Texture\" end");
  EXPECT_NE(error.find("33 keyframes; at most 32"), std::string::npos) << error;
  error = refusal("ClearAllFrame BeginKeyFrame 12 1 Animate 3 \"Texture\" end ClearAllFrame BeginKeyFrame 4 1 Animate 3 \"Texture\" end");
  EXPECT_NE(error.find("at most one of each"), std::string::npos) << error;
}

// Vascular scripts nest three deep (emotion, stage, expression); brackets
// past what the grammar allows are a syntax error where the first is.
TEST(RoomScript, OverDeepNestingIsASyntaxErrorAtItsPlace) {
  const std::string deep = "[emotion e [stage1 duration 100 [expression x intensity 1.0 " + std::string(1000, '[') +
                           std::string(1003, ']');
  const std::string error = refusal(deep);
  EXPECT_EQ(error.rfind("script 1:61: ", 0), 0u) << error;
}

TEST(RoomScript, WhatARoomDoesNotPlayIsRefusedSayingWhatToSend) {
  EXPECT_NE(refusal("[expression x [mpca nose intensity 0.2]]")
                .find("no expression sentence, vascular emotion or AU definition"),
            std::string::npos);
  const std::string error = refusal("[emotion e [stage1 duration 100 [expression flush intensity 0.5]]]");
  EXPECT_NE(error.find("uses 'flush', not defined in the script"), std::string::npos) << error;
}

}  // namespace
}  // namespace fw::behavior
