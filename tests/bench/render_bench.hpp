#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench render`: frames per second of the OSMesa renderer.
void add_render_bench(CLI::App& app);

}  // namespace fw::bench
