#include "codec_bench.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "codec_run.hpp"
#include "fw/codec/codec.hpp"
#include "photo_variants.hpp"
#include "synthetic_correctives.hpp"
#include "synthetic_scene.hpp"
#include "x264_comparison.hpp"
#include "bench_failure.hpp"

namespace fw::bench {
namespace {

struct CodecBenchArgs {
  bool json = false;
  std::vector<std::string> scene_files;
  double target_bps = 500;
  int refresh_ticks = 0;     // as the room server's streams do: 2
  std::uint64_t seed = 1;
  double seconds = 60;       // of the synthetic scene
  std::string write_scene_path;
  bool video = true;         // the x264 comparison (renders and codes video: about a minute)
  std::string photo;         // the portrait of the rendered avatar
};

// The reference points the issue compares against.
constexpr double kPaperBytesPerFrame = 8600;  // behavioral-animation paper, per face per frame
constexpr double kGoalBps = 500, kGoalGazeDeg = 0.5, kGoalIdleBps = 50, kGoalRmsMm = 0.5;
constexpr double kGoalCorrectiveBps = 60;  // per avatar, what the corrective channels may add

double round_to(double v, double unit) { return std::round(v / unit) * unit; }

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

struct Rates {
  double mean = 0;          // bits per second, mean over the avatars
  double p99 = 0;           // 99th percentile of any avatar's bits in any 1-second window
  double bits_per_tick = 0;
  double bits_per_frame = 0;  // per frame that went out
  double frames_per_second = 0;
  std::size_t avatars = 0;
};

Rates rates(const CodecRun& run, bool idle) {
  Rates r;
  std::vector<double> windows;
  double total_bits = 0, ticks = 0, frames = 0;
  for (const AvatarRun& a : run.avatars) {
    if (a.idle != idle) continue;
    ++r.avatars;
    const double bits = std::accumulate(a.bits_per_tick.begin(), a.bits_per_tick.end(), 0.0);
    total_bits += bits;
    ticks += static_cast<double>(a.bits_per_tick.size());
    frames += static_cast<double>(a.frames);
    const auto w = static_cast<std::size_t>(run.fps);
    double sum = 0;
    for (std::size_t t = 0; t < a.bits_per_tick.size(); ++t) {
      sum += a.bits_per_tick[t];
      if (t >= w) sum -= a.bits_per_tick[t - w];
      if (t + 1 >= w) windows.push_back(sum);
    }
  }
  if (r.avatars == 0 || ticks == 0) return r;
  r.mean = total_bits / ticks * run.fps;
  r.p99 = percentile(windows, 0.99);
  r.bits_per_tick = total_bits / ticks;
  r.bits_per_frame = frames > 0 ? total_bits / frames : 0;
  r.frames_per_second = frames / ticks * run.fps;
  return r;
}

// The x264 side of the comparison for one avatar of the scene; also sets
// the scene entry's `x264_over_ours`.
nlohmann::json x264_entry(const Scene& scene, int avatar, const CodecRun& run, const CodecBenchArgs& args,
                          nlohmann::json& entry) {
  const auto& track = scene.avatars[static_cast<std::size_t>(avatar)];
  const auto& bits = run.avatars[static_cast<std::size_t>(avatar)].bits_per_tick;
  const double ours_bps = std::accumulate(bits.begin(), bits.end(), 0.0) / static_cast<double>(bits.size()) * run.fps;
  std::vector<codec::FaceParams> original;
  for (const codec::FaceParams& p : track.ticks) original.push_back(in_range(p));
  const X264Comparison c = compare_with_x264(original, run.recorded, ours_bps, run.fps, args.photo);
  if (!c.skipped.empty()) return {{"avatar", track.name}, {"skipped", c.skipped}};
  entry["x264_over_ours"] = round_to(c.x264_bps / c.ours_bps, 0.1);
  return {{"avatar", track.name},
          {"frames", c.frames},
          {"size", "256x256"},
          {"ours_bps", round_to(c.ours_bps, 0.1)},
          {"ours_psnr_db", round_to(c.ours_psnr_db, 0.01)},
          {"x264_bps", round_to(c.x264_bps, 1.0)},
          {"x264_crf", c.x264_crf},
          {"x264_psnr_db", round_to(c.x264_psnr_db, 0.01)},
          {"x264_reached_our_psnr", c.x264_reached},
          {"x264_settings", c.x264_settings}};
}

// What the corrective channels cost: the scene's stream with moving
// corrective weights minus the same stream with none, at the bench's budget
// and a few larger ones (they ride only on spare budget, so what they cost
// and how closely they follow depends on what the rest of the face leaves).
// A scene recorded without correctives gets synthetic ones, made from its
// action units (synthetic_correctives.hpp), until the room simulation
// records the physics face's own.
nlohmann::json corrective_cost(const Scene& scene, const CodecRunOptions& base) {
  const bool recorded = has_correctives(scene);
  Scene with = scene;
  if (!recorded) add_synthetic_correctives(with, 1);
  Scene without = scene;
  clear_correctives(without);
  auto row = [&](double target) {
    CodecRunOptions options = base;
    options.record_avatar = -1;
    options.target_bps_per_avatar = target;
    const CodecRun moving = run_codec(with, options);
    const double cost = rates(moving, false).mean - rates(run_codec(without, options), false).mean;
    return nlohmann::json{{"target_bps", target},
                          {"corrective_bps", round_to(cost, 0.1)},
                          {"corrective_rms_error", round_to(moving.corrective_rms_error, 0.0001)},
                          {"corrective_max_error", round_to(moving.corrective_max_error, 0.0001)}};
  };
  nlohmann::json entry = row(base.target_bps_per_avatar);
  entry["source"] = recorded ? "recorded" : "synthetic, from the action units";
  entry["corrective_bps_max"] = kGoalCorrectiveBps;
  entry["corrective_bps_met"] = entry["corrective_bps"].get<double>() <= kGoalCorrectiveBps;
  entry["by_budget"] = nlohmann::json::array();
  for (const double factor : {1.5, 2.0, 4.0}) entry["by_budget"].push_back(row(base.target_bps_per_avatar * factor));
  return entry;
}

nlohmann::json scene_entry(const Scene& scene, const CodecBenchArgs& args) {
  CodecRunOptions options;
  options.target_bps_per_avatar = args.target_bps;
  options.refresh_ticks = args.refresh_ticks;
  // The video comparison follows the first active avatar.
  int video_avatar = -1;
  for (std::size_t a = 0; a < scene.avatars.size() && video_avatar < 0; ++a)
    if (!scene.avatars[a].idle) video_avatar = static_cast<int>(a);
  if (args.video) options.record_avatar = video_avatar;
  const CodecRun run = run_codec(scene, options);
  const Rates active = rates(run, false);
  const Rates idle = rates(run, true);
  std::uint64_t keys = 0;
  for (const AvatarRun& a : run.avatars) keys += a.key_frames;
  nlohmann::json entry = {
      {"name", scene.name},
      {"avatars", scene.avatars.size()},
      {"active_avatars", active.avatars},
      {"idle_avatars", idle.avatars},
      {"seconds", round_to(static_cast<double>(scene.tick_count()) / scene.fps, 0.01)},
      {"fps", scene.fps},
      {"target_bps_per_avatar", args.target_bps},
      {"refresh_ticks", args.refresh_ticks},
      {"bps_mean_per_avatar", round_to(active.mean, 0.1)},
      {"bps_p99_per_avatar", round_to(active.p99, 0.1)},
      {"bits_per_frame_mean", round_to(active.bits_per_tick, 0.01)},
      {"bits_per_sent_frame_mean", round_to(active.bits_per_frame, 0.1)},
      {"frames_sent_per_second", round_to(active.frames_per_second, 0.01)},
      {"key_frames", keys},
      {"room_frames", run.room_frames},
      {"room_bytes", run.room_bytes},
      {"rms_mm", round_to(run.vertex_rms_mm, 0.001)},
      {"max_mm", round_to(run.vertex_max_mm, 0.001)},
      {"gaze_max_deg", round_to(run.gaze_max_deg, 0.001)},
      {"eye_in_head_max_deg", round_to(run.eye_in_head_max_deg, 0.001)},
      {"head_rotation_max_deg", round_to(run.head_rotation_max_deg, 0.001)},
      {"head_translation_max_mm", round_to(run.head_translation_max_mm, 0.001)},
      {"au_max_error", round_to(run.au_max_error, 0.0001)},
      {"au_rms_error", round_to(run.au_rms_error, 0.0001)},
      {"lid_max_error", round_to(run.lid_max_error, 0.0001)},
      {"colour_max_error", round_to(run.colour_max_error, 0.0001)},
      {"decode_mismatches", run.decode_errors},
  };
  if (idle.avatars > 0) {
    entry["idle_bps_mean"] = round_to(idle.mean, 0.1);
    entry["idle_bps_p99"] = round_to(idle.p99, 0.1);
  }
  entry["goal"] = {{"bps_mean_max", kGoalBps},
                   {"gaze_max_deg", kGoalGazeDeg},
                   {"rms_mm_max", kGoalRmsMm},
                   {"idle_bps_max", kGoalIdleBps},
                   {"bps_met", active.mean <= kGoalBps},
                   {"rms_met", run.vertex_rms_mm <= kGoalRmsMm},
                   {"gaze_met", run.gaze_max_deg <= kGoalGazeDeg}};
  if (idle.avatars > 0) entry["goal"]["idle_met"] = idle.mean < kGoalIdleBps;
  if (args.video && video_avatar >= 0) entry["x264"] = x264_entry(scene, video_avatar, run, args, entry);
  entry["correctives"] = corrective_cost(scene, options);
  entry["corrective_bps"] = entry["correctives"]["corrective_bps"];

  // The same scene over an unreliable transport: sequence numbers, periodic
  // key frames and heartbeats cost extra.
  options.loss_tolerant = true;
  const CodecRun lossy = run_codec(scene, options);
  const Rates lossy_active = rates(lossy, false);
  const Rates lossy_idle = rates(lossy, true);
  std::uint64_t lossy_keys = 0;
  for (const AvatarRun& a : lossy.avatars) lossy_keys += a.key_frames;
  entry["loss_tolerant"] = {{"bps_mean_per_avatar", round_to(lossy_active.mean, 0.1)},
                            {"bps_p99_per_avatar", round_to(lossy_active.p99, 0.1)},
                            {"rms_mm", round_to(lossy.vertex_rms_mm, 0.001)},
                            {"max_mm", round_to(lossy.vertex_max_mm, 0.001)},
                            {"gaze_max_deg", round_to(lossy.gaze_max_deg, 0.001)},
                            {"au_max_error", round_to(lossy.au_max_error, 0.0001)},
                            {"key_frames", lossy_keys},
                            {"decode_mismatches", lossy.decode_errors}};
  if (lossy_idle.avatars > 0) entry["loss_tolerant"]["idle_bps_mean"] = round_to(lossy_idle.mean, 0.1);
  return entry;
}

nlohmann::json rd_row(const CodecRun& run) {
  const Rates active = rates(run, false);
  const Rates idle = rates(run, true);
  nlohmann::json row = {{"bps_mean_per_avatar", round_to(active.mean, 0.1)},
                    {"bps_p99_per_avatar", round_to(active.p99, 0.1)},
                    {"frames_sent_per_second", round_to(active.frames_per_second, 0.01)},
                    {"rms_mm", round_to(run.vertex_rms_mm, 0.001)},
                    {"max_mm", round_to(run.vertex_max_mm, 0.001)},
                    {"gaze_max_deg", round_to(run.gaze_max_deg, 0.001)},
                    {"head_rotation_max_deg", round_to(run.head_rotation_max_deg, 0.001)},
                    {"au_max_error", round_to(run.au_max_error, 0.0001)},
                    {"au_rms_error", round_to(run.au_rms_error, 0.0001)},
                    {"lid_max_error", round_to(run.lid_max_error, 0.0001)}};
  if (idle.avatars > 0) row["idle_bps_mean"] = round_to(idle.mean, 0.1);
  return row;
}

// Rows over budgets (the rate control at work, levels 3-7 by default), and
// over fixed quality levels with no budget (what each level costs and gives).
nlohmann::json rd_table(const Scene& scene) {
  nlohmann::json rows = nlohmann::json::array();
  for (const double target : {150.0, 250.0, 350.0, 500.0, 750.0, 1000.0, 2000.0}) {
    CodecRunOptions options;
    options.target_bps_per_avatar = target;
    nlohmann::json row = rd_row(run_codec(scene, options));
    row["target_bps"] = target;
    rows.push_back(row);
  }
  nlohmann::json levels = nlohmann::json::array();
  for (int level = 0; level <= codec::kMaxQualityLevel; ++level) {
    CodecRunOptions options;
    options.target_bps_per_avatar = 1.0e6;
    options.min_level = options.max_level = level;
    nlohmann::json row = rd_row(run_codec(scene, options));
    row["level"] = level;
    row["tolerance_factor"] = codec::kLevelFactor[static_cast<std::size_t>(level)];
    levels.push_back(row);
  }
  return {{"scene", scene.name}, {"rows", rows}, {"fixed_levels", levels}};
}

void run(const CodecBenchArgs& args) {
  std::vector<Scene> scenes;
  if (args.scene_files.empty()) {
    SyntheticSceneOptions options;
    options.seed = args.seed;
    options.seconds = args.seconds;
    scenes.push_back(make_synthetic_scene(options));
    if (!args.write_scene_path.empty()) {
      std::string error;
      if (!write_scene(scenes.back(), args.write_scene_path, error)) fail_bench("codec", error);
    }
  }
  for (const std::string& path : args.scene_files) {
    Scene scene;
    std::string error;
    if (!read_scene(path, scene, error)) fail_bench("codec", error);
    scenes.push_back(std::move(scene));
  }
  const int fps = scenes.front().fps;
  nlohmann::json out = {
      {"benchmark", "codec"},
      {"format_version", codec::kFormatVersion},
      {"schema", codec::kFaceParamsSchema},
      {"channels", codec::kChannelCount},
      {"stream_header_bytes", codec::write_stream_header({}).size()},
      {"target_bps_per_avatar", args.target_bps},
      {"raw_float32_bps_per_avatar", static_cast<double>(codec::kChannelCount) * 32.0 * fps},
      {"paper_bps_per_avatar", kPaperBytesPerFrame * 8.0 * fps},
      {"scenes", nlohmann::json::array()},
  };
  for (const Scene& scene : scenes) out["scenes"].push_back(scene_entry(scene, args));
  out["rd_table"] = rd_table(scenes.front());
  for (const auto& entry : out["scenes"])
    if (entry["decode_mismatches"].get<std::uint64_t>() != 0 ||
        entry["loss_tolerant"]["decode_mismatches"].get<std::uint64_t>() != 0)
      fail_bench("codec", "the decoder disagreed with the encoder's reconstruction on scene " + entry["name"].get<std::string>());
  if (args.json) {
    std::cout << out.dump() << "\n";
    return;
  }
  for (const auto& e : out["scenes"]) {
    std::cout << e["name"].get<std::string>() << ": " << e["bps_mean_per_avatar"] << " bit/s mean per active avatar (p99 "
              << e["bps_p99_per_avatar"] << "), gaze max " << e["gaze_max_deg"] << " deg";
    if (e.contains("idle_bps_mean")) std::cout << ", idle " << e["idle_bps_mean"] << " bit/s";
    std::cout << "\n";
  }
  std::cout << "raw float32: " << out["raw_float32_bps_per_avatar"] << " bit/s; paper: " << out["paper_bps_per_avatar"]
            << " bit/s\n";
}

}  // namespace

void add_codec_bench(CLI::App& app) {
  auto args = std::make_shared<CodecBenchArgs>();
  CLI::App* cmd = app.add_subcommand("codec", "Bit rate and distortion of the FaceParams codec");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->add_option("--scene", args->scene_files, "scene file(s) (.fws from facewire-server simulate, or .fwscene) instead of the synthetic scene")
      ->check(CLI::ExistingFile);
  cmd->add_option("--target-bps", args->target_bps, "bit budget per avatar")
      ->check(CLI::Range(50.0, 1.0e6))
      ->capture_default_str();
  cmd->add_option("--refresh-ticks", args->refresh_ticks,
                  "send a face that moved at least every N ticks, as the room server does with 2 (0: off)")
      ->check(CLI::Range(0, 300))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "seed of the synthetic scene")->capture_default_str();
  cmd->add_option("--seconds", args->seconds, "length of the synthetic scene")
      ->check(CLI::Range(1.0, 3600.0))
      ->capture_default_str();
  cmd->add_flag("!--no-video", args->video, "leave out the x264 comparison (it renders and codes video)");
  args->photo = test::astronaut_path();
  cmd->add_option("--photo", args->photo, "portrait of the avatar rendered for the x264 comparison")
      ->capture_default_str();
  cmd->add_option("--write-scene", args->write_scene_path, "also write the synthetic scene to this file");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
