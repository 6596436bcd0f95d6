#include "fw/behavior/expression_envelope.hpp"

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(ExpressionEnvelope, AttackDecaySustainRelease) {
  ExpressionEnvelope e;
  e.attack_s = 0.2;
  e.decay_s = 0.2;
  e.sustain_s = 1.0;
  e.release_s = 0.5;
  e.peak = 1;
  e.sustain_level = 0.6f;
  EXPECT_EQ(e.at(-0.1), 0);
  EXPECT_EQ(e.at(0), 0);
  EXPECT_NEAR(e.at(0.2), 1, 1e-6);
  EXPECT_NEAR(e.at(0.9), 0.6, 1e-6);
  EXPECT_NEAR(e.at(1.65), 0.3, 1e-6);
  EXPECT_EQ(e.at(1.9), 0);
  EXPECT_NEAR(e.length_s(), 1.9, 1e-9);
}

TEST(ExpressionEnvelope, CommandsHoldWhatWasAskedForTheirDuration) {
  const ExpressionEnvelope calm = envelope_for(3, 0.6f, 0);
  const ExpressionEnvelope emphatic = envelope_for(3, 0.6f, 1);
  EXPECT_LT(emphatic.attack_s, calm.attack_s);
  EXPECT_GT(emphatic.peak, calm.peak);
  EXPECT_NEAR(emphatic.at(emphatic.attack_s + 2.5), 0.6, 1e-5);
  EXPECT_NEAR(calm.decay_s + calm.sustain_s, 3, 1e-9);
}

}  // namespace
}  // namespace fw::behavior
