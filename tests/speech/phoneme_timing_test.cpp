#include "fw/speech/phoneme_timing.hpp"

#include <gtest/gtest.h>

#include "speech_compare.hpp"

namespace fw::speech {
namespace {

PhonemeTiming timed(std::string_view text, std::string_view language = "en", SpeechLimits limits = {}) {
  PhonemeTiming timing;
  std::string error;
  EXPECT_TRUE(time_phonemes(text, language, limits, timing, error)) << error;
  return timing;
}

constexpr const char* kLongLine =
    "This is a rather long chat line that keeps going and going, far beyond what anyone would "
    "want to hear from an avatar in one breath, because it has a great deal to say about the "
    "weather, the news, the food at lunch, and the many reasons why a meeting should have ended "
    "an hour ago, before anyone noticed that the coffee had run out and the lights went dim.";

TEST(PhonemeTiming, PhonemesFollowEachOtherAcrossTheAudio) {
  const PhonemeTiming t = timed("Hello, my name is Paul.");
  EXPECT_EQ(t.sample_rate_hz, 22050);
  ASSERT_FALSE(t.phonemes.empty());
  // The lead: silence before the voice.
  EXPECT_EQ(t.phonemes.front().name, "_");
  EXPECT_GE(t.phonemes.front().end_s, PhonemeTiming::kLeadS - 0.001);
  const auto lead_samples = static_cast<std::size_t>(PhonemeTiming::kLeadS * t.sample_rate_hz);
  ASSERT_GT(t.samples.size(), lead_samples);
  for (std::size_t i = 0; i < lead_samples; ++i) ASSERT_EQ(t.samples[i], 0) << i;
  EXPECT_GT(t.length_s(), 1.0);
  EXPECT_LT(t.length_s(), 2.5);
  for (std::size_t i = 0; i < t.phonemes.size(); ++i) {
    EXPECT_LE(t.phonemes[i].start_s, t.phonemes[i].end_s);
    if (i > 0) {
      EXPECT_EQ(t.phonemes[i].start_s, t.phonemes[i - 1].end_s);
    }
  }
  EXPECT_NEAR(t.phonemes.back().end_s, t.length_s(), 0.002);
  bool has_p = false;
  for (const auto& p : t.phonemes) has_p = has_p || p.name == "p";
  EXPECT_TRUE(has_p);
  EXPECT_FALSE(t.truncated);
  EXPECT_EQ(t.spoken_bytes, std::string_view("Hello, my name is Paul.").size());
}

TEST(PhonemeTiming, OtherLanguagesHaveTheirOwnPhonemes) {
  const PhonemeTiming de = timed("Zwölf Boxkämpfer jagen Viktor.", "de");
  bool has_ts = false;
  for (const auto& p : de.phonemes) has_ts = has_ts || p.name == "ts";
  EXPECT_TRUE(has_ts);
  EXPECT_FALSE(timed("Bonjour tout le monde.", "fr").phonemes.empty());
  EXPECT_FALSE(timed("Buenos días.", "es").phonemes.empty());
  EXPECT_FALSE(timed("Hello.", "EN-US").phonemes.empty());  // as the voice files spell it, or not
}

TEST(PhonemeTiming, AnUnknownLanguageIsRefusedByName) {
  PhonemeTiming t;
  std::string error;
  EXPECT_FALSE(time_phonemes("Hello", "klingon", SpeechLimits{}, t, error));
  EXPECT_NE(error.find("'klingon'"), std::string::npos) << error;
  EXPECT_NE(error.find(", en,"), std::string::npos) << error;  // and lists those there are
  EXPECT_NE(error.find(", de,"), std::string::npos) << error;
  // Even for a line with nothing to say.
  EXPECT_FALSE(time_phonemes("", "klingon", SpeechLimits{}, t, error));
}

TEST(PhonemeTiming, NothingToSayIsAnEmptyTimeline) {
  for (const char* text : {"", "   ", "\xF0\x9F\x98\x80\xF0\x9F\x99\x82", ":-) !!!"}) {
    const PhonemeTiming t = timed(text);
    EXPECT_TRUE(t.phonemes.empty()) << text;
    EXPECT_TRUE(t.samples.empty()) << text;
    EXPECT_FALSE(t.truncated);
  }
}

TEST(PhonemeTiming, TextBeyondTheByteLimitIsRefused) {
  PhonemeTiming t;
  std::string error;
  const std::string text(SpeechLimits::kMaxTextBytes + 1, 'a');
  EXPECT_FALSE(time_phonemes(text, "en", SpeechLimits{}, t, error));
  EXPECT_NE(error.find("501 bytes"), std::string::npos) << error;
}

TEST(PhonemeTiming, ALongLineIsCutAtAWordBoundary) {
  const std::string text = kLongLine;
  ASSERT_LE(text.size(), SpeechLimits::kMaxTextBytes);
  const PhonemeTiming t = timed(text);
  ASSERT_TRUE(t.truncated);
  const double speech_s = t.length_s() - PhonemeTiming::kLeadS;
  EXPECT_LE(speech_s, SpeechLimits{}.max_seconds);
  EXPECT_GT(speech_s, SpeechLimits{}.max_seconds - 1.0);  // a word is under a second
  EXPECT_LE(t.phonemes.back().end_s, t.length_s() + 1e-9);
  ASSERT_GT(t.spoken_bytes, 0u);
  ASSERT_LT(t.spoken_bytes, text.size());
  EXPECT_EQ(text[t.spoken_bytes], ' ');  // a word ends there
  // Said alone, the spoken part fits (its own end pause aside).
  const PhonemeTiming spoken = timed(text.substr(0, t.spoken_bytes));
  EXPECT_FALSE(spoken.truncated);
  EXPECT_NEAR(spoken.length_s(), t.length_s(), 0.6);
  std::printf("cut after %zu of %zu bytes, %.2f s: \"...%s\"\n", t.spoken_bytes, text.size(), t.length_s(),
              text.substr(t.spoken_bytes - 20, 20).c_str());
}

TEST(PhonemeTiming, AShortLimitCutsTheFirstWordItself) {
  SpeechLimits limits;
  limits.max_seconds = 0.1;
  const PhonemeTiming t = timed("Incomprehensibilities abound.", "en", limits);
  EXPECT_TRUE(t.truncated);
  EXPECT_EQ(t.spoken_bytes, 0u);
  EXPECT_NEAR(t.length_s(), PhonemeTiming::kLeadS + 0.1, 0.001);
}

TEST(PhonemeTiming, ACutSynthesisLeavesNothingBehind) {
  const PhonemeTiming before = timed("Good morning, everyone.");
  SpeechLimits limits;
  limits.max_seconds = 1.0;
  EXPECT_TRUE(timed(kLongLine, "en", limits).truncated);
  EXPECT_TRUE(test::same_speech(timed("Good morning, everyone."), before));
}

}  // namespace
}  // namespace fw::speech
