#include "synthetic_scene.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "fw/codec/codec.hpp"

namespace fw::bench {
namespace {

TEST(SyntheticScene, IsTheSameSceneForTheSameSeed) {
  SyntheticSceneOptions o;
  o.seconds = 5;
  const Scene a = make_synthetic_scene(o), b = make_synthetic_scene(o);
  o.seed = 2;
  const Scene c = make_synthetic_scene(o);
  ASSERT_EQ(a.tick_count(), 150u);
  EXPECT_EQ(a.name, "synthetic-seed1");
  bool differs = false;
  for (std::size_t t = 0; t < a.tick_count(); ++t)
    for (std::size_t c2 = 0; c2 < codec::kChannelCount; ++c2) {
      ASSERT_EQ(codec::channel_value(a.avatars[0].ticks[t], c2), codec::channel_value(b.avatars[0].ticks[t], c2));
      differs = differs || codec::channel_value(a.avatars[0].ticks[t], c2) != codec::channel_value(c.avatars[0].ticks[t], c2);
    }
  EXPECT_TRUE(differs);
}

TEST(SyntheticScene, HasTheEventsTheCodecMustCarry) {
  const Scene s = make_synthetic_scene({});
  ASSERT_EQ(s.avatars.size(), 5u);
  EXPECT_EQ(s.tick_count(), 1800u);
  for (const SceneAvatar& a : s.avatars) {
    int blinks = 0, saccades = 0, turns = 0;
    float max_au = 0, max_colour = 0;
    for (std::size_t t = 1; t < a.ticks.size(); ++t) {
      const auto& p = a.ticks[t];
      const auto& q = a.ticks[t - 1];
      blinks += p.lid_left > 0.6f && q.lid_left <= 0.6f;
      const double gaze = std::hypot(p.eye_left.yaw_rad + p.head_yaw_rad - q.eye_left.yaw_rad - q.head_yaw_rad,
                                     p.eye_left.pitch_rad + p.head_pitch_rad - q.eye_left.pitch_rad - q.head_pitch_rad);
      saccades += gaze > 1.0 * 3.14159 / 180;  // ticks inside a saccade
      turns += std::abs(p.head_yaw_rad - q.head_yaw_rad) > 0.2 * 3.14159 / 180;
      for (float v : p.au) max_au = std::max(max_au, v);
      for (float v : p.blush) max_colour = std::max(max_colour, v);
      max_colour = std::max(max_colour, p.pallor);
      for (std::size_t c = 0; c < codec::kChannelCount; ++c) ASSERT_TRUE(std::isfinite(codec::channel_value(p, c)));
    }
    EXPECT_GE(blinks, 8) << a.name;
    EXPECT_GT(saccades, a.idle ? 5 : 40) << a.name;
    if (a.idle) {
      EXPECT_EQ(max_au, 0.0f) << a.name << ": no expressions";
      EXPECT_EQ(max_colour, 0.0f);
    } else {
      EXPECT_GT(max_au, 0.5f) << a.name;
      EXPECT_GT(max_colour, 0.25f) << a.name << ": a blush or pallor episode";
      EXPECT_GT(turns, 30) << a.name << ": head turns";
    }
  }
}

}  // namespace
}  // namespace fw::bench
