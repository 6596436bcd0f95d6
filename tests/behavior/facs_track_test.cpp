#include "fw/behavior/facs_track.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "test_paths.hpp"

namespace fw::behavior {
namespace {

std::size_t channel(int au, codec::AuSide side = codec::AuSide::both) {
  return static_cast<std::size_t>(codec::au_channel(au, side));
}

TEST(FacsTrack, ASentenceBecomesTimedTargets) {
  AuTrack t;
  std::string error;
  ASSERT_TRUE(facs_track("ClearAllFrame BeginKeyFrame 12 2.0 6 0.5 Animate 5 \"Texture\" end", t, error)) << error;
  const std::size_t au12 = channel(12, codec::AuSide::left);
  EXPECT_EQ(t.at(0)[au12], 0);
  EXPECT_NEAR(t.at(0.5)[au12], 1.0f, 1e-5f);  // 5 steps of 0.1 s; 2.0 is the full strength
  EXPECT_NEAR(t.at(0.25)[au12], 0.5f, 1e-5f);
  EXPECT_NEAR(t.at(0.5)[channel(6, codec::AuSide::left)], 0.25f, 1e-5f);
  EXPECT_NEAR(t.length_s(), 0.5 + AuTrack::kHoldS + AuTrack::kReleaseS, 1e-9);
  EXPECT_EQ(t.at(t.length_s())[au12], 0);
}

TEST(FacsTrack, ErrorsSayWhatWasWrong) {
  AuTrack t;
  std::string error;
  EXPECT_FALSE(facs_track("ClearAllFrame BeginKeyFrame 3 1.0 Animate 2 \"Texture\" end", t, error));
  EXPECT_NE(error.find("AU 3"), std::string::npos) << error;
  EXPECT_NE(error.find("line 1 column 29"), std::string::npos) << error;
  EXPECT_FALSE(facs_track("[expression x [mpca nose intensity 0.2]]", t, error));
  EXPECT_NE(error.find("no expression sentence"), std::string::npos) << error;
}

// A face smiling, the jaw at rest: what KeepAllFrame is given.
AuTargets smiling() {
  codec::FaceParams p;
  p.set_au(12, 0.7f);
  p.set_au(6, 0.4f);
  return p.au;
}

TEST(FacsTrack, KeepAllFrameKeepsTheFaceItFindsAndComesBackToIt) {
  AuTrack t;
  std::string error;
  ASSERT_TRUE(facs_track("KeepAllFrame BeginKeyFrame 26 1.6 Animate 4 \"Texture\" end", smiling(), t, error)) << error;
  EXPECT_EQ(t.at(0), smiling()) << "it starts from the face as it is";
  const AuTargets peak = t.at(0.4);
  EXPECT_NEAR(peak[channel(26)], 0.8f, 1e-5f);
  EXPECT_NEAR(peak[channel(12, codec::AuSide::left)], 0.7f, 1e-5f) << "the smile it found stays";
  EXPECT_NEAR(peak[channel(6, codec::AuSide::right)], 0.4f, 1e-5f);
  EXPECT_EQ(t.at(t.length_s()), smiling()) << "and it ends where it began";
}

TEST(FacsTrack, ClearAllFrameStartsFromTheNeutralFace) {
  AuTrack t;
  std::string error;
  ASSERT_TRUE(facs_track("ClearAllFrame BeginKeyFrame 26 1.6 Animate 4 \"Texture\" end", smiling(), t, error)) << error;
  EXPECT_EQ(t.at(0), AuTargets{});
  EXPECT_NEAR(t.at(0.4)[channel(26)], 0.8f, 1e-5f);
  EXPECT_EQ(t.at(0.4)[channel(12, codec::AuSide::left)], 0) << "keyframes are full poses";
  EXPECT_EQ(t.at(t.length_s()), AuTargets{});
}

// The pose of a script's last keyframe, once its Animate has played.
AuTargets played_pose(const std::string& script) {
  AuTrack t;
  std::string error;
  EXPECT_TRUE(facs_track(script, t, error)) << error << "\n" << script;
  return t.at(t.length_s() - AuTrack::kReleaseS);
}

// Expression `e` at `x` written as a script: each action unit at twice its
// share (2 is an action unit's full strength on the script's scale).
std::string as_script(model::Expression e, float x) {
  std::string text = "ClearAllFrame BeginKeyFrame";
  for (const model::ExpressionComponent& c : model::expression_definition(e).action_units) {
    char number[32];
    std::snprintf(number, sizeof number, " %d %.6f", c.au, 2.0 * c.intensity * x);
    text += number;
  }
  return text + " Animate 3 \"Texture\" end";
}

// One scale: a script's intensities mean what `express`'s do.
TEST(FacsTrack, AnExpressionWrittenAsAScriptIsTheBuiltInExpression) {
  for (std::size_t i = 0; i < model::kExpressionCount; ++i) {
    const auto e = static_cast<model::Expression>(i);
    // Teasing is one-sided; the script language has no sides (both sides move).
    if (e == model::Expression::teasing) continue;
    for (const float x : {0.25f, 0.6f, 1.0f}) {
      codec::FaceParams built_in;
      model::apply_expression(e, x, built_in);
      const AuTargets scripted = played_pose(as_script(e, x));
      for (std::size_t c = 0; c < scripted.size(); ++c)
        EXPECT_NEAR(scripted[c], built_in.au[c], 1e-5f)
            << model::kExpressionNames[i] << " at " << x << ", AU " << int{codec::kAuChannels[c].au};
    }
  }
}

// The paper's anger sentence, as printed, is the built-in anger at full
// strength (whose table is the paper's intensities halved).
TEST(FacsTrack, ThePapersAngerSentenceIsTheBuiltInAnger) {
  std::ifstream in(test::source_path("avatar/behavior/script/examples/anger.fws"));
  std::stringstream text;
  text << in.rdbuf();
  codec::FaceParams built_in;
  model::apply_expression(model::Expression::anger, 1.0f, built_in);
  const AuTargets scripted = played_pose(text.str());
  for (std::size_t c = 0; c < scripted.size(); ++c)
    EXPECT_NEAR(scripted[c], built_in.au[c], 1e-5f) << "AU " << int{codec::kAuChannels[c].au};
}

}  // namespace
}  // namespace fw::behavior
