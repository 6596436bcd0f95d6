#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench codec`: bit rate and parameter distortion of the codec on
/// the synthetic standard scene (or scene files), with a rate-distortion table.
void add_codec_bench(CLI::App& app);

}  // namespace fw::bench
