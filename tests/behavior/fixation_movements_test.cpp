#include "fw/behavior/fixation_movements.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

TEST(FixationMovements, DriftStaysSmallAndMicroSaccadesRecoverIt) {
  FixationMovements f(3);
  float worst = 0;
  for (int i = 0; i < 30 * 60; ++i) {
    const YawPitch o = f.step(1.0 / 30);
    worst = std::max(worst, std::hypot(o.yaw_rad, o.pitch_rad));
  }
  EXPECT_LT(worst, 0.5f * 0.0175f);  // half a degree
  EXPECT_GT(f.microsaccades(), 5);    // about one every few seconds
  EXPECT_LT(f.microsaccades(), 200);
}

}  // namespace
}  // namespace fw::behavior
