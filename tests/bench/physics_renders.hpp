#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench physics-renders`: a disgust and a wide jaw opening,
/// shortly after onset and settled, rendered as the kinematic fallback, the
/// physics face as a client rebuilds it from the stream, and the simulated
/// skin itself, side by side; prints their distances as JSON.
void add_physics_renders(CLI::App& app);

}  // namespace fw::bench
