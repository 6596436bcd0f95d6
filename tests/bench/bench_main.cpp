// facewire-bench: every benchmark of the project, each printing one JSON
// object with --json.
#include <iostream>

#include <CLI/CLI.hpp>

#include "codec_bench.hpp"
#include "fanout_bench.hpp"
#include "physics_renders.hpp"
#include "prep_bench.hpp"
#include "render_bench.hpp"
#include "sim_bench.hpp"

int main(int argc, char** argv) {
  CLI::App app{"facewire benchmarks"};
  app.require_subcommand(1);
  fw::bench::add_render_bench(app);
  fw::bench::add_prep_bench(app);
  fw::bench::add_codec_bench(app);
  fw::bench::add_fanout_bench(app);
  fw::bench::add_sim_bench(app);
  fw::bench::add_physics_renders(app);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
