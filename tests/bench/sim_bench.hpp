#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench sim`: face-frames per second of the physics face (every
/// solver, or one), bytes per face and the measurement's residual, for many faces
/// on a thread pool.
void add_sim_bench(CLI::App& app);

}  // namespace fw::bench
