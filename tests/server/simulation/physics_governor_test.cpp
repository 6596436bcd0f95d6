#include "physics_governor.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

using Clock = PhysicsGovernor::Clock;
using std::chrono::milliseconds;

constexpr auto kPeriod = std::chrono::microseconds(33'333);

// One window of `ticks` room ticks, `late` of them starting a whole period
// late; returns the clock after it.
Clock::time_point run_window(PhysicsGovernor& governor, Clock::time_point t, int ticks, int late) {
  for (int i = 0; i < ticks; ++i) {
    const auto due = t + milliseconds(1000) * i / ticks;
    governor.observe_tick(due, i < late ? due + kPeriod : due + milliseconds(1), kPeriod);
  }
  return t + milliseconds(1000);
}

TEST(PhysicsGovernor, BacksOffWhileTicksAreLateAndComesBackSlowly) {
  PhysicsGovernor governor(true, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  EXPECT_EQ(governor.share(), 1.0);
  for (int w = 0; w < 3; ++w) t = run_window(governor, t, 300, 100);
  EXPECT_NEAR(governor.share(), 0.7 * 0.7, 1e-9) << "two windows closed late (the first tick opens the first)";
  const double low = governor.share();
  t = run_window(governor, t, 300, 0);
  EXPECT_NEAR(governor.share(), low * 0.7, 1e-9) << "the third late window closes at this window's first tick";
  t = run_window(governor, t, 300, 0);
  EXPECT_NEAR(governor.share(), low * 0.7 + PhysicsGovernor::kRecovery, 1e-9);
  for (int w = 0; w < 40; ++w) t = run_window(governor, t, 300, 0);
  EXPECT_EQ(governor.share(), 1.0) << "on time for long enough: every face has physics again";
}

TEST(PhysicsGovernor, AFewLateTicksChangeNothing) {
  PhysicsGovernor governor(true, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  for (int w = 0; w < 5; ++w) t = run_window(governor, t, 300, 9);  // 3 %
  EXPECT_EQ(governor.share(), 1.0);
}

TEST(PhysicsGovernor, WhenDisabledEveryFaceKeepsPhysics) {
  PhysicsGovernor governor(false, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  for (int w = 0; w < 5; ++w) t = run_window(governor, t, 300, 300);
  EXPECT_EQ(governor.share(), 1.0);
  governor.set_enabled(true);
  for (int w = 0; w < 5; ++w) t = run_window(governor, t, 300, 300);
  EXPECT_LT(governor.share(), 0.5);
  governor.set_enabled(false);
  EXPECT_EQ(governor.share(), 1.0);
}

}  // namespace
}  // namespace fw::server
