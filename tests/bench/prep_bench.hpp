#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench prep`: milliseconds per photo of avatar preparation and
/// the package size.
void add_prep_bench(CLI::App& app);

}  // namespace fw::bench
