// facewire-bench: every benchmark of the project, each printing one JSON
// object with --json. Benchmarks whose subsystem is not built yet say so.
#include <iostream>

#include <CLI/CLI.hpp>

#include "fw/photo/photo_limits.hpp"
#include "codec_bench.hpp"
#include "prep_bench.hpp"
#include "render_bench.hpp"

int main(int argc, char** argv) {
  fw::photo::enforce_decoder_pixel_limit(argv);
  CLI::App app{"facewire benchmarks"};
  app.require_subcommand(1);
  fw::bench::add_render_bench(app);
  fw::bench::add_prep_bench(app);
  fw::bench::add_codec_bench(app);
  const std::pair<const char*, const char*> unbuilt[] = {
      {"sim", "the physics face"}, {"fanout", "the room server"}};
  for (const auto& [name, what] : unbuilt) {
    CLI::App* cmd = app.add_subcommand(name, std::string("Benchmark of ") + what + " (not yet built)");
    cmd->allow_extras();
    cmd->callback([name = std::string(name), what = std::string(what)] {
      std::cerr << "facewire-bench " << name << ": not yet built; it arrives with " << what << ".\n";
      std::exit(3);
    });
  }
  CLI11_PARSE(app, argc, argv);
  return 0;
}
