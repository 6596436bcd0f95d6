#include "physics_governor.hpp"

#include <algorithm>

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

TEST(PhysicsGovernor, AStrayLateTickDoesNotStopPhysicsComingBack) {
  PhysicsGovernor governor(true, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  for (int w = 0; w < 3; ++w) t = run_window(governor, t, 300, 100);
  const double low = governor.share();
  ASSERT_LT(low, 0.5);
  for (int w = 0; w < 5; ++w) t = run_window(governor, t, 300, 2);  // under 1 %: a time slice elsewhere
  // The third late window closes at the first of these (as above); the
  // other four give back.
  EXPECT_NEAR(governor.share(), low * 0.7 + 4 * PhysicsGovernor::kRecovery, 1e-9);
}

// A window as run_window, the rooms reporting `room_s` of their own work and
// `physics_s` of their faces' tissue over it.
Clock::time_point run_costed_window(PhysicsGovernor& governor, Clock::time_point t, int late, double room_s,
                                    double physics_s) {
  governor.observe_room_work(room_s);
  governor.observe_physics_work(physics_s);
  return run_window(governor, t, 300, late);
}

TEST(PhysicsGovernor, LateTicksShedPhysicsOnlyWhilePhysicsFillsThePool) {
  PhysicsGovernor governor(true, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  // Late, the tissue a tenth of the work: encoders or other processes fill
  // the cores, and shedding physics would not bring the ticks back.
  for (int w = 0; w < 10; ++w) t = run_costed_window(governor, t, 300, 1.8, 0.2);
  EXPECT_EQ(governor.share(), 1.0) << "physics is kept while it is not what makes the ticks late";
  // Late, the tissue half of the work: shed, window after window.
  for (int w = 0; w < 4; ++w) t = run_costed_window(governor, t, 300, 1.0, 1.0);
  EXPECT_LT(governor.share(), 0.5);
  // Still late, but with less physics the tissue is under a third: held there.
  const double held = (t = run_costed_window(governor, t, 300, 1.8, 0.55), governor.share());
  for (int w = 0; w < 10; ++w) t = run_costed_window(governor, t, 300, 1.8, 0.55);
  EXPECT_EQ(governor.share(), held) << "held where the tissue no longer fills the pool";
  EXPECT_GT(governor.share(), 0.2);
  // On time again: back, slowly.
  for (int w = 0; w < 3; ++w) t = run_costed_window(governor, t, 0, 1.0, 0.5);
  EXPECT_GT(governor.share(), held);
}

TEST(PhysicsGovernor, TheShareSettlesWhereThePoolCarriesIt) {
  // A pool that keeps its ticks while the rooms' work is at most 1.6 s a
  // second, the tissue costing 2 s a second with every face on physics and
  // the rest 1 s: the share settles around (1.6 - 1) / 2 = 0.3, shedding
  // while late and the tissue at least a third of the work (always so here
  // above a share of 0.25).
  PhysicsGovernor governor(true, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  double low = 1, high = 0;
  for (int w = 0; w < 200; ++w) {
    const double share = governor.share();
    const double physics_s = 2.0 * share;
    const bool late = 1.0 + physics_s > 1.6;
    t = run_costed_window(governor, t, late ? 300 : 0, 1.0, physics_s);
    if (w >= 100) {
      low = std::min(low, governor.share());
      high = std::max(high, governor.share());
    }
  }
  const double k = PhysicsGovernor::kPhysicsPartToShed;
  EXPECT_GE(low, k / (1 - k) / 2 - 1e-9) << "never below where the tissue takes a third of the work";
  EXPECT_LT(high, 0.40);
}

TEST(PhysicsGovernor, ALateWindowCutsTheShareNoFurtherThanWhereTheTissueTakesItsPart) {
  EXPECT_EQ(PhysicsGovernor::back_off(0.8, 0.2), 1.0) << "a fifth: not the tissue's doing";
  EXPECT_EQ(PhysicsGovernor::back_off(1.0, 1.0), PhysicsGovernor::kBackOff) << "half: the deepest cut";
  EXPECT_EQ(PhysicsGovernor::back_off(0, 0), PhysicsGovernor::kBackOff) << "no work reported";
  // 37 %: cut, to where the tissue's cost (following the share) is a third
  // of the work, where a cut by 30 % would go below it.
  const double cut = PhysicsGovernor::back_off(0.63, 0.37);
  EXPECT_LT(cut, 1.0);
  EXPECT_GT(cut, PhysicsGovernor::kBackOff);
  EXPECT_NEAR(0.37 * cut / (0.63 + 0.37 * cut), PhysicsGovernor::kPhysicsPartToShed, 1e-9);
}

TEST(PhysicsGovernor, AHundredRoomsOfTenKeepAQuarterOfTheirFacesOnPhysicsAndMostTicks) {
  // 100 rooms of 10 on 2 cores (server/README.md): at a share of 0.33 the
  // tissue took some 36 % of the workers' time, so per second at 30 Hz
  // about 0.72 s of the rooms' own work and 1.2 s of tissue with every face
  // on physics; the cores carried a share of 0.31 at 30 Hz, say 0.33. Cut
  // by 30 % from there, the share fell to 0.23-0.24.
  PhysicsGovernor governor(true, milliseconds(1000));
  Clock::time_point t{};
  t += milliseconds(5);
  double low = 1, high = 0;
  int late_windows = 0;
  for (int w = 0; w < 200; ++w) {
    const double physics_s = 1.2 * governor.share();
    const bool late = 0.72 + physics_s > 0.72 + 1.2 * 0.33;
    t = run_costed_window(governor, t, late ? 300 : 0, 0.72, physics_s);
    if (w >= 100) {
      low = std::min(low, governor.share());
      high = std::max(high, governor.share());
      late_windows += late ? 1 : 0;
    }
  }
  EXPECT_GE(low, 0.25) << "a quarter of the faces keep physics";
  EXPECT_LT(high, 0.40);
  EXPECT_LE(late_windows, 50) << "at most every other window a little late, as the share probes upward";
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
