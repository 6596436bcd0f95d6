#include "fw/behavior/plateau_motion.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

// A smile held for ten seconds wavers a little around where it is held; a
// channel at rest stays at rest.
TEST(PlateauMotion, AHeldExpressionWaversAroundItsLevel) {
  const int smile = codec::au_channel(12, codec::AuSide::left);
  const int jaw = codec::au_channel(26, codec::AuSide::both);
  float lo = 1, hi = 0, moves = 0;
  double sum = 0;
  long last = -1;
  const int ticks = 30 * 10;
  for (int i = 0; i < ticks; ++i) {
    std::array<float, codec::kAuChannelCount> au{};
    au[static_cast<std::size_t>(smile)] = 0.6f;
    add_plateau_motion(au, i / 30.0, 17);
    const float v = au[static_cast<std::size_t>(smile)];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
    // What the codec sends: the value in steps of 1/256.
    const long step = std::lround(v * 256);
    if (last >= 0 && step != last) ++moves;
    last = step;
    EXPECT_EQ(au[static_cast<std::size_t>(jaw)], 0.0f);
  }
  std::printf("held at 0.6: %.3f .. %.3f, mean %.3f\n", lo, hi, sum / ticks);
  EXPECT_GT(hi - lo, 0.02f) << "the plateau is frozen";
  EXPECT_LT(hi - lo, 0.08f) << "no new expression";
  EXPECT_NEAR(sum / ticks, 0.6, 0.015);
  std::printf("the coded value changed %.0f times in 10 s\n", moves);
  EXPECT_GT(moves, 20) << "it moves often enough to be seen";
}

TEST(PlateauMotion, FacesWaverDifferently) {
  const auto smile = static_cast<std::size_t>(codec::au_channel(12, codec::AuSide::left));
  std::array<float, codec::kAuChannelCount> a{}, b{};
  a[smile] = b[smile] = 0.6f;
  add_plateau_motion(a, 3.3, 1);
  add_plateau_motion(b, 3.3, 2);
  EXPECT_NE(a[smile], b[smile]);
}

}  // namespace
}  // namespace fw::behavior
