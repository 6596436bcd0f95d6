#include "fw/behavior/chat_appraisal.hpp"

#include <string>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

float of(const EmotionPoint& p, Primary x) { return p[static_cast<std::size_t>(x)]; }

TEST(ChatAppraisal, LaughterEmoticonsMarksAndWords) {
  EXPECT_GT(of(appraise_chat("hahaha that was good"), Primary::joy), 0.3f);
  EXPECT_GT(of(appraise_chat("see you :)"), Primary::joy), 0.3f);
  EXPECT_GT(of(appraise_chat("I miss you :("), Primary::sadness), 0.4f);
  EXPECT_GT(of(appraise_chat("WOW!!!"), Primary::surprise), 0.6f);
  EXPECT_GT(of(appraise_chat("that is gross"), Primary::disgust), 0.3f);
  EXPECT_GT(of(appraise_chat("I'm scared"), Primary::fear), 0.3f);
  EXPECT_GT(of(appraise_chat("really?"), Primary::surprise), 0.2f);
  EXPECT_EQ(label(classify(appraise_chat("the meeting is at ten"))), "neutral");
  // Words count whole: "hatever" is no hate, "grossly" no disgust.
  EXPECT_EQ(of(appraise_chat("whatever, grossly"), Primary::anger), 0);
  EXPECT_EQ(of(appraise_chat("whatever, grossly"), Primary::disgust), 0);
}

TEST(ChatAppraisal, BoundedForAnyInput) {
  const std::string spam(100000, '!');
  const EmotionPoint p = appraise_chat(spam);
  for (float v : p) {
    EXPECT_GE(v, 0);
    EXPECT_LE(v, 1);
  }
}

TEST(ChatAppraisal, EmbarrassmentIsTold) {
  for (const char* line : {"oops, wrong room", "Whoops!", "my bad", "this is so embarrassing", "I'm blushing",
                           "awkward...", "ok :$", "\xF0\x9F\x98\xB3"})
    EXPECT_TRUE(embarrassing_chat(line)) << line;
  for (const char* line : {"hello there", "great :)", "loopsided", "my badge", ""})
    EXPECT_FALSE(embarrassing_chat(line)) << line;
}

}  // namespace
}  // namespace fw::behavior
