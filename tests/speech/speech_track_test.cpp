#include "fw/speech/speech_track.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "generic_mouth.hpp"
#include "speech_compare.hpp"

namespace fw::speech {
namespace {

struct Spoken {
  PhonemeTiming timing;
  SpeechTrack track;
};

Spoken speak(std::string_view text, std::string_view language = "en", SpeechLimits limits = {}) {
  Spoken s;
  std::string error;
  EXPECT_TRUE(time_phonemes(text, language, limits, s.timing, error)) << error;
  s.track = speech_track(s.timing);
  return s;
}

constexpr double kSampleHz = 100;

std::vector<double> mouth_opening(const test::GenericMouth& mouth, const SpeechTrack& track) {
  std::vector<double> gaps;
  const auto count = static_cast<std::size_t>(track.length_s() * kSampleHz) + 1;
  for (std::size_t k = 0; k < count; ++k) gaps.push_back(mouth.gap_mm(track.at(static_cast<double>(k) / kSampleHz)));
  return gaps;
}

// The loudness of the audio: RMS over a 50 ms window around each of the
// same instants. (Chandrasekaran et al., "The natural statistics of
// audiovisual speech", PLoS Comput. Biol. 5(7), 2009, found the area of
// real speakers' mouths to follow the speech envelope at 2-7 Hz.)
std::vector<double> loudness(const PhonemeTiming& timing, std::size_t count) {
  std::vector<double> rms;
  const auto half = static_cast<std::ptrdiff_t>(0.025 * timing.sample_rate_hz);
  const auto n = static_cast<std::ptrdiff_t>(timing.samples.size());
  for (std::size_t k = 0; k < count; ++k) {
    const auto centre = static_cast<std::ptrdiff_t>(static_cast<double>(k) / kSampleHz * timing.sample_rate_hz);
    double sum = 0;
    for (std::ptrdiff_t i = std::max<std::ptrdiff_t>(0, centre - half); i < std::min(n, centre + half); ++i)
      sum += double(timing.samples[static_cast<std::size_t>(i)]) * timing.samples[static_cast<std::size_t>(i)];
    rms.push_back(std::sqrt(sum / double(2 * half)));
  }
  return rms;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < n; ++i) ma += a[i], mb += b[i];
  ma /= double(n), mb /= double(n);
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

// Open-close cycles: maxima of the opening that rise at least `min_mm`
// above the lowest point since the previous one and fall as far after it.
int opening_cycles(const std::vector<double>& gaps, double min_mm) {
  int cycles = 0;
  double low = gaps.empty() ? 0 : gaps.front(), high = low;
  bool rising = true;
  for (double g : gaps) {
    if (rising) {
      high = std::max(high, g);
      if (high - g >= min_mm && high - low >= min_mm) {
        ++cycles;
        rising = false;
        low = g;
      }
      low = rising ? std::min(low, g) : low;
    } else {
      low = std::min(low, g);
      if (g - low >= min_mm) {
        rising = true;
        high = g;
      }
    }
  }
  return cycles;
}

const std::pair<const char*, const char*> kSentences[] = {
    {"en", "Hello everyone, it is good to see you all here today."},
    {"en", "The quick brown fox jumps over the lazy dog."},
    {"en", "I think we should meet again on Monday to talk about the plan."},
    {"en", "Could you please pass me the map before we go back home?"},
    {"de", "Guten Morgen, wie geht es dir heute?"},
    {"fr", "Bonjour à tous, je suis très content de vous voir."},
};

TEST(SpeechTrack, TheMouthOpensWithTheVoice) {
  const test::GenericMouth mouth;
  for (const auto& [language, text] : kSentences) {
    const Spoken s = speak(text, language);
    // Over the audio only, not the track's closing time after it.
    std::vector<double> gaps = mouth_opening(mouth, s.track);
    gaps.resize(std::min(gaps.size(), static_cast<std::size_t>(s.timing.length_s() * kSampleHz)));
    const double r = correlation(gaps, loudness(s.timing, gaps.size()));
    std::printf("r = %.3f  [%s] %s\n", r, language, text);
    EXPECT_GE(r, 0.5) << text;
  }
}

TEST(SpeechTrack, TheMouthIsStillBeforeAndAfterTheLine) {
  const Spoken s = speak("Nice to meet you.");
  ASSERT_FALSE(s.track.empty());
  EXPECT_NEAR(s.track.length_s(), s.timing.length_s() + SpeechTrack::kCloseS, SpeechTrack::kKeyStepS);
  for (double t : {-1.0, -0.01, 0.0, s.track.length_s(), s.track.length_s() + 0.01, 100.0})
    EXPECT_EQ(s.track.at(t), AuTargets{}) << t;
  // No jump from rest into the track or out of it: the lead and the
  // closing time bring the mouth to rest before the zeros at either end.
  const auto& keys = s.track.keys;
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    EXPECT_LT(keys[1][c], 0.01f) << c;
    EXPECT_LT(keys[keys.size() - 2][c], 0.01f) << c;
  }
  const test::GenericMouth mouth;
  double widest = 0;
  for (double g : mouth_opening(mouth, s.track)) widest = std::max(widest, g);
  EXPECT_GT(widest, 6.0);  // it did speak: a vowel opens 6 mm and more
}

TEST(SpeechTrack, DiphthongsGlideAndSilentPhonemesHaveNoSegment) {
  const std::vector<TimedPhoneme> phonemes = {
      {"_", 0.0, 0.1}, {"b", 0.1, 0.16}, {"aI", 0.16, 0.36}, {"(en)", 0.36, 0.36}, {"t", 0.36, 0.36}};
  const std::vector<VisemeSegment> segments = viseme_segments(phonemes);
  ASSERT_EQ(segments.size(), 4u);
  EXPECT_EQ(segments[0].viseme, Viseme::rest);
  EXPECT_EQ(segments[1].viseme, Viseme::bilabial);
  EXPECT_EQ(segments[2].viseme, Viseme::open_vowel);
  EXPECT_EQ(segments[3].viseme, Viseme::close_front_vowel);
  EXPECT_DOUBLE_EQ(segments[2].end_s, 0.26);
  EXPECT_DOUBLE_EQ(segments[3].start_s, 0.26);
}

TEST(SpeechTrack, KeysAreInterpolated) {
  SpeechTrack track;
  AuTargets open{};
  open[5] = 1.0f;
  track.keys = {AuTargets{}, open, AuTargets{}};
  EXPECT_DOUBLE_EQ(track.length_s(), 2 * SpeechTrack::kKeyStepS);
  EXPECT_FLOAT_EQ(track.at(0.25 * SpeechTrack::kKeyStepS)[5], 0.25f);
  EXPECT_FLOAT_EQ(track.at(SpeechTrack::kKeyStepS)[5], 1.0f);
  EXPECT_FLOAT_EQ(track.at(1.5 * SpeechTrack::kKeyStepS)[5], 0.5f);
}

TEST(SpeechTrack, BilabialsCloseTheLipsAtTheirTime) {
  const test::GenericMouth mouth;
  int closures = 0;
  for (const char* text : {"Could you please pass me the map before we go back home?",
                           "My mother bought a bag of apples by the pub."}) {
    const Spoken s = speak(text);
    for (const auto& p : s.timing.phonemes) {
      if (p.name != "p" && p.name != "b" && p.name != "m") continue;
      const double middle = 0.5 * (p.start_s + p.end_s);
      // Closed: the lips touch (no gap), where the resting face has a 1 mm slit.
      EXPECT_EQ(mouth.gap_mm(s.track.at(middle)), 0.0f) << p.name << " at " << middle << " s in " << text;
      ++closures;
    }
  }
  EXPECT_GE(closures, 12);
}

TEST(SpeechTrack, OrdinaryEnglishOpensFourToFiveTimesASecond) {
  // Syllables come at about 4-5 a second in English (Greenberg, "Speaking
  // in shorthand", Speech Communication 29, 1999; the mouth's opening is
  // modulated at 2-7 Hz, peaking near 4: Chandrasekaran et al. 2009), and
  // each opens and closes the jaw and lips once.
  const Spoken s = speak(
      "I went to the market this morning to buy some bread and cheese. The weather was nice, "
      "so I walked along the river and stopped for a coffee with a friend.");
  const std::vector<double> gaps = mouth_opening(test::GenericMouth{}, s.track);
  const int cycles = opening_cycles(gaps, 1.0);
  // Per second of speaking (the articulation rate): pauses left out.
  double speaking_s = 0;
  for (const auto& p : s.timing.phonemes)
    if (p.name.front() != '_') speaking_s += p.end_s - p.start_s;
  const double rate_hz = cycles / speaking_s;
  std::printf("%d open-close cycles in %.2f s of speaking: %.2f per second\n", cycles, speaking_s, rate_hz);
  EXPECT_GE(rate_hz, 3.5);
  EXPECT_LE(rate_hz, 5.5);
}

TEST(SpeechTrack, ALongLineSaysItWasCut) {
  SpeechLimits limits;
  limits.max_seconds = 2.0;
  const std::string text = "One two three four five six seven eight nine ten eleven twelve.";
  const Spoken s = speak(text, "en", limits);
  EXPECT_TRUE(s.track.truncated);
  EXPECT_LE(s.track.length_s(), PhonemeTiming::kLeadS + 2.0 + SpeechTrack::kCloseS + SpeechTrack::kKeyStepS);
  EXPECT_GT(s.track.spoken_bytes, 0u);
  EXPECT_LT(s.track.spoken_bytes, text.size());
  EXPECT_EQ(s.track.at(s.track.length_s()), AuTargets{});
  EXPECT_FALSE(speak("One two.").track.truncated);
}

TEST(SpeechTrack, NothingToSayIsAnEmptyTrack) {
  for (const char* text : {"", "\xF0\x9F\x98\x82\xF0\x9F\x98\x82\xF0\x9F\x98\x82", "... !?"}) {
    const Spoken s = speak(text);
    EXPECT_TRUE(s.track.empty()) << text;
    EXPECT_EQ(s.track.length_s(), 0.0);
    EXPECT_EQ(s.track.at(0.0), AuTargets{});
  }
}

TEST(SpeechTrack, AnUnknownLanguageMakesNoTrack) {
  PhonemeTiming timing;
  std::string error;
  EXPECT_FALSE(time_phonemes("Hello", "xx-nowhere", SpeechLimits{}, timing, error));
  EXPECT_NE(error.find("'xx-nowhere'"), std::string::npos) << error;
  EXPECT_TRUE(speech_track(timing).empty());
}

// The tracks of two syntheses of one line: the same phonemes (speech_compare.hpp),
// and at every key the targets of the other track within the timing drift.
bool same(const Spoken& a, const Spoken& b) {
  if (!test::same_speech(a.timing, b.timing)) return false;
  const auto drift_keys = static_cast<std::ptrdiff_t>(std::ceil(test::kSynthesisDriftS / SpeechTrack::kKeyStepS));
  const auto count = static_cast<std::ptrdiff_t>(std::min(a.track.keys.size(), b.track.keys.size()));
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    float closest = 1;
    for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, k - drift_keys); j <= std::min(count - 1, k + drift_keys); ++j) {
      float worst = 0;
      for (std::size_t c = 0; c < codec::kAuChannelCount; ++c)
        worst = std::max(worst, std::abs(a.track.keys[std::size_t(k)][c] - b.track.keys[std::size_t(j)][c]));
      closest = std::min(closest, worst);
    }
    if (closest > 0.05f) return false;
  }
  return true;
}

TEST(SpeechTrack, TwoThreadsAtOnceMakeWhatOneMakesAlone) {
  // Different voices, so a race would mix one thread's voice into the
  // other's line.
  const Spoken english_alone = speak("Shall we have lunch together?", "en");
  const Spoken german_alone = speak("Sollen wir zusammen essen gehen?", "de");
  constexpr int kRounds = 8;
  int english_same = 0, german_same = 0;
  std::thread english([&] {
    for (int i = 0; i < kRounds; ++i) english_same += same(speak("Shall we have lunch together?", "en"), english_alone);
  });
  std::thread german([&] {
    for (int i = 0; i < kRounds; ++i) german_same += same(speak("Sollen wir zusammen essen gehen?", "de"), german_alone);
  });
  english.join();
  german.join();
  EXPECT_EQ(english_same, kRounds);
  EXPECT_EQ(german_same, kRounds);
}

// What a line costs a core: printed for the record, never asserted.
double milliseconds_to_speak(std::string_view line, int rounds) {
  double total_ms = 0;
  for (int i = 0; i < rounds; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const Spoken s = speak(line);
    total_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    EXPECT_FALSE(s.track.empty());
  }
  return total_ms / rounds;
}

TEST(SpeechTrack, HowLongALineTakes) {
  constexpr const char* kTenWords = "We could try the new place around the corner this evening.";
  speak(kTenWords);  // espeak-ng starts and loads its voice once
  const double ten_words_ms = milliseconds_to_speak(kTenWords, 10);
  // The most a line can cost: one cut at 15 s.
  constexpr const char* kLongest =
      "one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen "
      "seventeen eighteen nineteen twenty twenty-one twenty-two twenty-three twenty-four twenty-five "
      "twenty-six twenty-seven twenty-eight twenty-nine thirty thirty-one thirty-two thirty-three "
      "thirty-four thirty-five thirty-six thirty-seven thirty-eight thirty-nine forty forty-one forty-two";
  ASSERT_TRUE(speak(kLongest).track.truncated);
  const double longest_ms = milliseconds_to_speak(kLongest, 3);
  std::printf("{\"ten_word_line_ms\": %.2f, \"fifteen_second_line_ms\": %.2f}\n", ten_words_ms, longest_ms);
}

}  // namespace
}  // namespace fw::speech
