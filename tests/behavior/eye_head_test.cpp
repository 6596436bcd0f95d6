#include "fw/behavior/eye_head.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

namespace fw::behavior {
namespace {

constexpr double kDt = 1.0 / 30;
constexpr float kDeg = 0.017453293f;

// A target 2 m away at `yaw` from straight ahead, at eye height.
glm::vec3 target_at(float yaw_rad) {
  const glm::vec3 eyes = head_geometry().eye_mid_mm;
  return eyes + 2000.0f * direction_from_angles({yaw_rad, 0.0f});
}

TEST(SaccadeMainSequence, DurationGrowsWithAmplitude) {
  EXPECT_NEAR(saccade_duration_s(10 * kDeg), 0.043, 0.002);
  EXPECT_NEAR(saccade_duration_s(60 * kDeg), 0.153, 0.002);
  EXPECT_LT(saccade_duration_s(5 * kDeg), saccade_duration_s(20 * kDeg));
}

class GazeStep : public ::testing::TestWithParam<std::uint64_t> {};

// Figure 8 of the paper: a 60-degree gaze shift, gaze on target quickly,
// the head contributing a part, the VOR holding gaze while the head finishes.
TEST_P(GazeStep, SixtyDegreeStepLandsFastWithHeadShareAndVorHolds) {
  const std::uint64_t seed = GetParam();
  std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
  EyeHeadController c({seed, true, true});
  c.look_at(target_at(0));
  for (int i = 0; i < 60; ++i) c.step(kDt);  // settle on the first target
  const float head_start = c.head().yaw_rad;
  const float goal = 60 * kDeg;
  c.look_at(target_at(goal));
  double landed_at = -1;
  float head_share = 0;
  float worst_after = 0;
  for (int i = 1; i <= 90; ++i) {
    c.step(kDt);
    const float error = std::abs(c.gaze().yaw_rad - c.target_direction().yaw_rad);
    if (landed_at < 0 && error < 2 * kDeg) {
      landed_at = i * kDt;
      head_share = (c.head().yaw_rad - head_start) / goal;
    } else if (landed_at >= 0) {
      worst_after = std::max(worst_after, error);
    }
  }
  ASSERT_GE(landed_at, 0) << "gaze never reached the target";
  std::printf("landed after %.0f ms, head share %.0f%%, worst gaze error after landing %.2f deg\n", landed_at * 1000,
              head_share * 100, worst_after / kDeg);
  EXPECT_LE(landed_at, 0.3);
  EXPECT_GE(head_share, 0.10f);
  EXPECT_LE(head_share, 0.40f);
  EXPECT_LT(worst_after, 1 * kDeg) << "the VOR let gaze slip while the head moved";
  // The head really kept moving after gaze landed.
  EXPECT_GT(c.head().yaw_rad - head_start, head_share * goal + 10 * kDeg);
}

// While the head finishes a large shift, the VOR holds the gaze: the eyes
// make the one saccade and no train of small corrective ones (a fixation
// check that paired this tick's head with last tick's eye saw the head's own
// motion as a gaze error and jumped after it every other frame).
TEST_P(GazeStep, ALargeShiftIsOneSaccadeWithoutCorrectiveSteps) {
  EyeHeadController c({GetParam(), true, true});
  c.look_at(target_at(0));
  for (int i = 0; i < 60; ++i) c.step(kDt);
  for (const float goal : {40 * kDeg, -30 * kDeg, 60 * kDeg}) {
    c.look_at(target_at(goal));
    int saccades = 0;
    for (int i = 0; i < 60; ++i) {
      c.step(kDt);
      saccades += c.saccade_started_rad() > 0 ? 1 : 0;
    }
    EXPECT_EQ(saccades, 1) << "a shift to " << goal / kDeg << " deg";
    EXPECT_LT(std::abs(c.gaze().yaw_rad - c.target_direction().yaw_rad), 2 * kDeg);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, GazeStep, ::testing::Values(1u, 2u, 3u, 99u));

// The head turns with a bell-shaped velocity: slow, fast, slow, its peak in
// the middle half of the movement, not in its first frame as a first-order
// lag would have it.
TEST(HeadMovement, VelocityIsBellShaped) {
  EyeHeadController c({4, false, false});
  c.look_at(target_at(0));
  for (int i = 0; i < 30; ++i) c.step(kDt);
  for (const float goal : {25 * kDeg, -20 * kDeg, 50 * kDeg, 0.0f}) {
    c.look_at(target_at(goal));
    std::vector<float> yaw{c.head().yaw_rad};
    for (int i = 0; i < 45; ++i) {
      c.step(kDt);
      yaw.push_back(c.head().yaw_rad);
    }
    // The move: from the first tick the head turns until it has covered
    // 98 % of its way.
    const float total = yaw.back() - yaw.front();
    ASSERT_GT(std::abs(total), 10 * kDeg) << goal / kDeg;
    std::size_t end = 1;
    while (end < yaw.size() && std::abs(yaw[end] - yaw.front()) < 0.98f * std::abs(total)) ++end;
    std::size_t peak = 1;
    for (std::size_t i = 1; i <= end && i < yaw.size(); ++i)
      if (std::abs(yaw[i] - yaw[i - 1]) > std::abs(yaw[peak] - yaw[peak - 1])) peak = i;
    const double at = static_cast<double>(peak) / static_cast<double>(end);
    std::printf("head move of %.0f deg over %zu ticks, peak velocity at %.0f %% of it\n", total / kDeg, end, at * 100);
    EXPECT_GE(at, 0.25) << goal / kDeg;
    EXPECT_LE(at, 0.75) << goal / kDeg;
    EXPECT_NEAR(head_movement_duration_s(std::abs(total)), 0.15 + 0.005 * std::abs(total) / kDeg, 1e-6);
  }
}

TEST(Vergence, EyesTurnInOnNearTargets) {
  EyeHeadController c({5, false, false});
  const glm::vec3 eyes = head_geometry().eye_mid_mm;
  c.look_at(eyes + glm::vec3(0, 0, 250));
  for (int i = 0; i < 60; ++i) c.step(kDt);
  codec::FaceParams p;
  c.write(p);
  const float expected = 2 * std::atan(0.5f * head_geometry().interocular_mm / 250.0f);
  EXPECT_NEAR(p.eye_right.yaw_rad - p.eye_left.yaw_rad, expected, 0.01f);
  c.look_at(eyes + glm::vec3(0, 0, 5000));
  for (int i = 0; i < 60; ++i) c.step(kDt);
  c.write(p);
  EXPECT_LT(p.eye_right.yaw_rad - p.eye_left.yaw_rad, 0.02f);
}

TEST(HeadNoise, TheHeadNeverFreezes) {
  EyeHeadController c({8, true, true});
  c.look_at(target_at(0));
  float lo = 1, hi = -1;
  for (int i = 0; i < 600; ++i) {
    c.step(kDt);
    lo = std::min(lo, c.head().roll_rad);
    hi = std::max(hi, c.head().roll_rad);
  }
  EXPECT_GT(hi - lo, 0.3f * kDeg);
  EXPECT_LT(hi - lo, 5 * kDeg);
}

}  // namespace
}  // namespace fw::behavior
