#include "fw/physics/stress_strain.hpp"

#include <gtest/gtest.h>

namespace fw::physics {
namespace {

TEST(Stress, IsLinearBelowTheKneeAndStifferAbove) {
  const StressStrainCurve curve{100.0f, 3.0f, 0.1f, 0.0f};
  EXPECT_FLOAT_EQ(stress(curve, 0.0f), 0.0f);
  EXPECT_FLOAT_EQ(stress(curve, 0.05f), 5.0f);
  EXPECT_FLOAT_EQ(stress(curve, -0.05f), -5.0f) << "compression stays on the low slope";
  EXPECT_FLOAT_EQ(stress(curve, 0.1f), 10.0f);
  EXPECT_FLOAT_EQ(stress(curve, 0.2f), 10.0f + 300.0f * 0.1f) << "collagen: three times the slope past the knee";
}

TEST(Stress, ANegativeResidualStrainMakesTheUnitSlackAtItsNeutralLength) {
  const StressStrainCurve normal{100.0f, 3.0f, 0.1f, 0.0f}, loose{100.0f, 3.0f, 0.1f, -0.05f, 0.0f};
  EXPECT_FLOAT_EQ(stress(loose, 0.0f), 0.0f) << "naturally longer and tension-only: no force at the neutral length";
  EXPECT_FLOAT_EQ(stress(loose, -0.1f), 0.0f) << "nor when pushed shorter";
  EXPECT_FLOAT_EQ(stress(loose, 0.05f), 0.0f) << "slack until stretched by the residual strain";
  EXPECT_FLOAT_EQ(stress(loose, 0.1f), 5.0f) << "then the low slope";
  for (float e : {0.1f, 0.2f}) EXPECT_LT(stress(loose, e), stress(normal, e)) << e;
  // With its compression kept, the same unit would push its ends apart at rest.
  const StressStrainCurve compressed{100.0f, 3.0f, 0.1f, -0.05f, 1.0f};
  EXPECT_FLOAT_EQ(stress(compressed, 0.0f), -5.0f);
}

}  // namespace
}  // namespace fw::physics
