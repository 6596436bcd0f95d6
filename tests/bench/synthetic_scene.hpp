#pragma once
// A deterministic synthetic room scene for the codec benchmark, until the
// behavior work records real ones: talking-table avatars with expression
// episodes (onset, hold, release), saccades with the main-sequence duration,
// head turns that follow large gaze shifts while the eyes counter-rotate
// (VOR), vergence, fixation drift and microsaccades, blinks, blushing and
// pallor, low-level head noise and breathing. Idle avatars (nobody at the
// keyboard) only rest, breathe, blink and glance about now and then.
#include <cstdint>

#include "fw/behavior/scene_file.hpp"

namespace fw::bench {

// Scene files moved to avatar/behavior, which records them.
using behavior::read_scene;
using behavior::Scene;
using behavior::SceneAvatar;
using behavior::write_scene;

struct SyntheticSceneOptions {
  std::uint64_t seed = 1;  ///< same seed, same scene, on every run
  int active_avatars = 4;
  int idle_avatars = 1;
  double seconds = 60.0;
  int fps = 30;
};

/// The scene; its name says the seed ("synthetic-seed1").
Scene make_synthetic_scene(const SyntheticSceneOptions& options);

}  // namespace fw::bench
