#include "prep_bench.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>

#include <nlohmann/json.hpp>

#include "fw/photo/prepare_avatar.hpp"
#include "photo_variants.hpp"
#include "bench_failure.hpp"

namespace fw::bench {
namespace {

struct PrepBenchArgs {
  int repeats = 3;
  bool json = false;
};

// Times prepare() on each large variant (JPEG bytes, as photos arrive), the
// model load excluded; the median of `repeats` runs per variant.
void run(const PrepBenchArgs& args) {
  cv::setNumThreads(1);  // the goal is per core: keep OpenCV's own threads out of it
  const cv::Mat original = test::load_astronaut();
  if (original.empty()) fail_bench("prep", "cannot read " + test::astronaut_path());
  photo::PrepError error;
  const auto load_start = std::chrono::steady_clock::now();
  auto preparer = photo::AvatarPreparer::create(std::nullopt, error);
  if (!preparer) fail_bench("prep", error.message);
  const double load_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();

  nlohmann::json per_variant = nlohmann::json::array();
  std::vector<double> medians;
  for (const test::PhotoVariant& variant : test::large_variants(original)) {
    const std::vector<std::uint8_t> jpeg = test::encode(variant.image, ".jpg");
    std::vector<double> times;
    for (int r = 0; r < args.repeats; ++r) {
      const auto start = std::chrono::steady_clock::now();
      const auto avatar = preparer->prepare(jpeg, {}, error);
      times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
      if (!avatar) fail_bench("prep", variant.name + ": " + error.message);
    }
    std::sort(times.begin(), times.end());
    medians.push_back(times[times.size() / 2]);
    per_variant.push_back({{"name", variant.name}, {"ms", std::round(medians.back() * 10) / 10},
                           {"width", variant.image.cols}, {"height", variant.image.rows}});
  }
  std::sort(medians.begin(), medians.end());

  const auto avatar = preparer->prepare(test::encode(original), {}, error);
  if (!avatar) fail_bench("prep", error.message);
  const auto package = model::serialize_avatar_package(avatar->package);
  const auto& p = avatar->package;
  nlohmann::json out = {
      {"benchmark", "prep"},
      {"ms_per_photo_median", std::round(medians[medians.size() / 2] * 10) / 10},
      {"variants", per_variant},
      {"model_load_ms", std::round(load_ms)},
      {"package_bytes", package.size()},
      {"package_members_bytes",
       {{"face_texture", p.face_texture.bytes.size()}, {"closed_lid", p.closed_lid.bytes.size()},
        {"eye", p.eye.bytes.size()}, {"mouth", p.mouth.bytes.size()},
        {"colour_masks", p.colour_masks_a.bytes.size() + p.colour_masks_b.bytes.size()},
        {"preview", p.preview.bytes.size()}}},
      {"threads", 1},
  };
  if (args.json) std::cout << out.dump() << "\n";
  else std::cout << out.dump(2) << "\n";
}

}  // namespace

void add_prep_bench(CLI::App& app) {
  auto args = std::make_shared<PrepBenchArgs>();
  CLI::App* cmd = app.add_subcommand("prep", "Milliseconds per photo of avatar preparation, and the package size");
  cmd->add_option("--repeats", args->repeats, "runs per variant (the median counts)")->check(CLI::Range(1, 50))->capture_default_str();
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
