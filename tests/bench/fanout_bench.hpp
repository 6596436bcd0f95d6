#pragma once
#include <CLI/CLI.hpp>

namespace fw::bench {

/// `facewire-bench fanout --rooms R --per-room N --seconds S --json`: starts
/// a facewire-server, joins R rooms of N real WebSocket clients on
/// loopback, and measures what reaches them (avatar frames per second,
/// latency from the simulation tick to the client's decode, the rooms' tick
/// rate) and what the server pays (CPU, resident memory). `--nodes N`
/// (N >= 2) runs the same rooms on a cluster of N nodes on a redis-server it
/// starts, every room's clients spread over the nodes, and adds Redis' CPU;
/// `cpu_us_per_avatar_frame` puts one node and a cluster on one scale.
/// `--nodes 1,2` runs each in turn and prints them side by side.
void add_fanout_bench(CLI::App& app);

}  // namespace fw::bench
