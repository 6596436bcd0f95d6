#include "fw/speech/visemes.hpp"

#include <algorithm>

#include <gtest/gtest.h>

#include "fw/speech/phoneme_timing.hpp"
#include "generic_mouth.hpp"

namespace fw::speech {
namespace {

Viseme first(std::string_view name) {
  const auto v = visemes_of(name);
  EXPECT_TRUE(v.has_value()) << name;
  return v ? v->first : Viseme::count;
}

TEST(Visemes, ConsonantsFallIntoTheirClasses) {
  for (auto name : {"p", "b", "m"}) EXPECT_EQ(first(name), Viseme::bilabial) << name;
  for (auto name : {"f", "v"}) EXPECT_EQ(first(name), Viseme::labiodental) << name;
  for (auto name : {"T", "D"}) EXPECT_EQ(first(name), Viseme::dental) << name;
  for (auto name : {"t", "d", "n", "l", "s", "z", "ts"}) EXPECT_EQ(first(name), Viseme::alveolar) << name;
  for (auto name : {"S", "Z", "tS", "dZ"}) EXPECT_EQ(first(name), Viseme::postalveolar) << name;
  for (auto name : {"k", "g", "N", "x"}) EXPECT_EQ(first(name), Viseme::velar) << name;
  EXPECT_EQ(first("h"), Viseme::glottal);
  EXPECT_EQ(first("r"), Viseme::rhotic);
  EXPECT_EQ(first("R2"), Viseme::rhotic);  // a variant number is not a symbol
  EXPECT_EQ(first("w"), Viseme::close_rounded_vowel);
  EXPECT_EQ(first("j"), Viseme::close_front_vowel);
  const auto pf = visemes_of("pF");  // German pf: closure, then the lip on the teeth
  ASSERT_TRUE(pf);
  EXPECT_EQ(pf->second, Viseme::labiodental);
}

TEST(Visemes, VowelsByOpennessAndRounding) {
  for (auto name : {"a", "A:", "aa", "a#", "V"}) EXPECT_EQ(first(name), Viseme::open_vowel) << name;
  for (auto name : {"e", "E", "@", "3:", "@-", "E~"}) EXPECT_EQ(first(name), Viseme::mid_vowel) << name;
  for (auto name : {"i", "I", "i:", "I2"}) EXPECT_EQ(first(name), Viseme::close_front_vowel) << name;
  for (auto name : {"o", "O:", "0", "Y:", "W"}) EXPECT_EQ(first(name), Viseme::open_rounded_vowel) << name;
  for (auto name : {"u:", "U", "y"}) EXPECT_EQ(first(name), Viseme::close_rounded_vowel) << name;
}

TEST(Visemes, DiphthongsGlideToTheirLastVowel) {
  const auto ai = visemes_of("aI");
  ASSERT_TRUE(ai);
  EXPECT_EQ(ai->first, Viseme::open_vowel);
  EXPECT_EQ(ai->second, Viseme::close_front_vowel);
  const auto ou = visemes_of("oU");
  ASSERT_TRUE(ou);
  EXPECT_EQ(ou->second, Viseme::close_rounded_vowel);
  const auto near = visemes_of("i@3");
  ASSERT_TRUE(near);
  EXPECT_EQ(near->first, Viseme::close_front_vowel);
  EXPECT_EQ(near->second, Viseme::mid_vowel);
}

TEST(Visemes, PausesRestAndMarkersHaveNoShape) {
  for (auto name : {"_", "_:", "_!", "_|"}) EXPECT_EQ(first(name), Viseme::rest) << name;
  EXPECT_FALSE(visemes_of("(en)"));
  EXPECT_FALSE(visemes_of(""));
  EXPECT_FALSE(visemes_of(";"));
}

// Every phoneme espeak-ng says in these lines has a shape; what it emits
// without one is only a language switch or its internal markers.
TEST(Visemes, EveryPhonemeOfTheFourVoicesHasAShape) {
  const std::pair<const char*, const char*> lines[] = {
      {"en", "The quick brown fox jumps over the lazy dog. She sells sea shells; the judge's vision."},
      {"en", "How now brown cow? The boy's toy, hair care, near here, tour poor, bird heard, father's car."},
      {"de", "Zwölf Boxkämpfer jagen Viktor quer über den großen Sylter Deich. Ich möchte ein Brötchen."},
      {"fr", "Portez ce vieux whisky au juge blond qui fume. Un bon vin blanc, le chien, huit, deux soeurs."},
      {"es", "El veloz murciélago hindú comía feliz cardillo y kiwi. Llueve en la calle, el niño, mucho."},
  };
  for (const auto& [language, text] : lines) {
    PhonemeTiming timing;
    std::string error;
    ASSERT_TRUE(time_phonemes(text, language, SpeechLimits{}, timing, error)) << error;
    for (const auto& p : timing.phonemes) {
      const bool marker = p.name.front() == '(' || p.name == "**" || p.name == ";";
      EXPECT_TRUE(marker || visemes_of(p.name).has_value()) << language << ": '" << p.name << "'";
    }
  }
}

TEST(Visemes, TargetsUseOnlyTheJawAndLips) {
  const int allowed[] = {10, 12, 14, 17, 20, 23, 24, 25, 26, 27};
  for (std::size_t v = 0; v < kVisemeCount; ++v) {
    const AuTargets& t = viseme_targets(static_cast<Viseme>(v));
    for (std::size_t c = 0; c < t.size(); ++c) {
      EXPECT_GE(t[c], 0.0f);
      EXPECT_LE(t[c], 1.0f);
      const int au = codec::kAuChannels[c].au;
      if (t[c] > 0) {
        EXPECT_NE(std::find(std::begin(allowed), std::end(allowed), au), std::end(allowed)) << au;
      }
    }
  }
  EXPECT_EQ(viseme_targets(Viseme::rest), AuTargets{});
  const auto jaw = static_cast<std::size_t>(codec::au_channel(26, codec::AuSide::both));
  EXPECT_GT(viseme_targets(Viseme::open_vowel)[jaw], viseme_targets(Viseme::mid_vowel)[jaw]);
  EXPECT_GT(viseme_targets(Viseme::mid_vowel)[jaw], viseme_targets(Viseme::close_front_vowel)[jaw]);
  EXPECT_EQ(viseme_targets(Viseme::bilabial)[jaw], 0.0f);
}

TEST(Visemes, TheyPartTheFacesLipsAsMuchAsASpeakers) {
  // The inner-lip gap on the generic face, against a speaker's at a
  // conversational level: 10-15 mm for /a/, half that for mid vowels, a
  // few millimetres for close vowels and the tongue consonants, none for
  // p b m.
  const test::GenericMouth mouth;
  auto gap = [&](Viseme v) { return mouth.gap_mm(viseme_targets(v)); };
  EXPECT_NEAR(gap(Viseme::open_vowel), 11.0f, 1.5f);
  EXPECT_NEAR(gap(Viseme::mid_vowel), 8.0f, 1.0f);
  EXPECT_NEAR(gap(Viseme::open_rounded_vowel), 7.0f, 1.0f);
  EXPECT_NEAR(gap(Viseme::close_front_vowel), 6.0f, 1.0f);
  EXPECT_NEAR(gap(Viseme::close_rounded_vowel), 6.0f, 1.0f);
  for (Viseme v : {Viseme::dental, Viseme::alveolar, Viseme::postalveolar, Viseme::velar, Viseme::rhotic,
                   Viseme::labiodental}) {
    EXPECT_GE(gap(v), gap(Viseme::rest)) << int(v);
    EXPECT_LE(gap(v), 3.5f) << int(v);
  }
  EXPECT_EQ(gap(Viseme::bilabial), 0.0f);
  EXPECT_NEAR(gap(Viseme::rest), 1.0f, 0.1f);
}

}  // namespace
}  // namespace fw::speech
