#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench fanout --rooms R --per-room N --seconds S --json`: starts
/// a facewire-server, joins R rooms of N real WebSocket clients on
/// loopback, and measures what reaches them (avatar frames per second,
/// latency from the simulation tick to the client's decode, the rooms' tick
/// rate) and what the server pays (CPU, resident memory).
void add_fanout_bench(CLI::App& app);

}  // namespace fw::bench
