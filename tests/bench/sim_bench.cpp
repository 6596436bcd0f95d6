#include "sim_bench.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fw/model/generic_face.hpp"
#include "fw/physics/face_pool.hpp"
#include "fw/physics/face_simulation.hpp"
#include "bench_failure.hpp"

namespace fw::bench {
namespace {

struct SimBenchArgs {
  int faces = 500;
  double seconds = 2.0;
  unsigned threads = 0;
  std::string solver = "massspring";
  double rate_hz = 30.0;
  std::uint64_t seed = 1;
  bool json = false;
};

// The reference points of issue 6 and the behavioral-animation paper's Table 1.
constexpr double kGoalFaceFramesPerS = 15000;   // 500 faces at 30 Hz on this 2-core machine
constexpr double kGoalBytesPerFace = 256 * 1024;
constexpr double kPaperFaceFramesPerS = 42.9;   // one face, one Pentium III thread
constexpr double kPaperBytesPerFace = 17.3e6;   // Table 1, one face

// Smooth, never-repeating AU targets, as the expression controller's
// envelopes give them: each face has a few active channels whose intensity
// drifts as a sum of two slow sines with seeded phases. Targets change every
// tick, so no face sleeps: the worst case for the simulation.
class Drive {
 public:
  Drive(std::uint64_t seed, int face) {
    std::uint64_t state = seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(face) * 0xbf58476d1ce4e5b9ULL + 1;
    auto next = [&] {
      state ^= state >> 33;
      state *= 0xff51afd7ed558ccdULL;
      state ^= state >> 33;
      return double(state >> 11) / double(1ULL << 53);
    };
    for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
      active_[c] = next() < 0.3;
      phase_[c] = 6.2831853 * next();
      rate_[c] = 0.2 + 0.6 * next();
    }
  }
  void targets(double t, std::array<float, codec::kAuChannelCount>& out) const {
    for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
      if (!active_[c]) {
        out[c] = 0.0f;
        continue;
      }
      const double s = 0.5 + 0.35 * std::sin(rate_[c] * 6.2831853 * t + phase_[c]) +
                       0.15 * std::sin(2.7 * rate_[c] * 6.2831853 * t + 2.0 * phase_[c]);
      out[c] = static_cast<float>(std::clamp(s, 0.0, 1.0));
    }
  }

 private:
  std::array<bool, codec::kAuChannelCount> active_{};
  std::array<double, codec::kAuChannelCount> phase_{}, rate_{};
};

void run(const SimBenchArgs& args) {
  if (args.faces < 1 || args.faces > 100000) fail_bench("sim", "--faces must be in 1..100000");
  if (!(args.seconds > 0.0) || args.seconds > 3600.0) fail_bench("sim", "--seconds must be in (0, 3600]");
  if (!(args.rate_hz >= 1.0) || args.rate_hz > 1000.0) fail_bench("sim", "--rate-hz must be in [1, 1000]");
  if (args.threads > 1024) fail_bench("sim", "--threads must be at most 1024 (0 = one per hardware thread)");
  physics::SimulationOptions options;
  if (args.solver == "massspring") options.solver = physics::Solver::mass_spring;
  else if (args.solver == "pbd") options.solver = physics::Solver::pbd;
  else fail_bench("sim", "--solver must be massspring or pbd, not '" + args.solver + "'");
  options.individual_variation = 0.05f;

  // One tissue model shared by all faces, as for faces of one avatar; every
  // avatar with its own fitted face has its own model, counted below.
  const auto tissue = physics::build_tissue_model(model::generic_face(), model::generic_face().action_units);
  std::vector<physics::FaceSimulation> faces;
  std::vector<Drive> drives;
  faces.reserve(static_cast<std::size_t>(args.faces));
  for (int i = 0; i < args.faces; ++i) {
    options.seed = args.seed + static_cast<std::uint64_t>(i);
    faces.emplace_back(tissue, options);
    drives.emplace_back(args.seed, i);
  }
  physics::FacePool pool(args.threads);
  const double dt = 1.0 / args.rate_hz;
  const int frames = std::max(1, static_cast<int>(std::lround(args.seconds * args.rate_hz)));
  std::vector<double> residual_sum(faces.size(), 0.0);
  std::vector<float> residual_max(faces.size(), 0.0f);

  // One tick of the server's pipeline per face: new targets, step, measure.
  auto tick = [&](int frame) {
    pool.for_each(faces.size(), [&](std::size_t i) {
      std::array<float, codec::kAuChannelCount> targets;
      drives[i].targets(frame * dt, targets);
      faces[i].set_action_units(targets);
      faces[i].step(dt);
      const float residual = faces[i].measure().residual_rms_mm;
      residual_sum[i] += residual;
      residual_max[i] = std::max(residual_max[i], residual);
    });
  };
  tick(0);  // warm up: caches, thread start
  // Wall time is what a server gets; CPU time (all threads) is what the
  // faces cost, whatever else the machine is running.
  const std::clock_t cpu_start = std::clock();
  const auto start = std::chrono::steady_clock::now();
  for (int f = 1; f <= frames; ++f) tick(f);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu_s = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;

  const double face_frames = double(frames) * double(faces.size());
  double residual_mean = 0.0;
  float residual_worst = 0.0f;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    residual_mean += residual_sum[i] / double(frames + 1);
    residual_worst = std::max(residual_worst, residual_max[i]);
  }
  residual_mean /= double(faces.size());
  const std::size_t state_bytes = faces.front().state_bytes(), model_bytes = tissue->memory_bytes();
  const double face_frames_per_s = face_frames / elapsed;

  nlohmann::json out;
  out["solver"] = args.solver;
  out["faces"] = args.faces;
  out["seconds"] = args.seconds;
  out["rate_hz"] = args.rate_hz;
  out["threads"] = pool.thread_count();
  out["nodes"] = tissue->node_count;
  out["moving_nodes"] = tissue->moving_node_count;
  out["springs"] = tissue->spring_count();
  out["muscles"] = tissue->muscles.size();
  out["elements"] = tissue->element_count();
  out["substeps_per_frame"] = faces.front().substeps_for(dt);
  out["face_frames_per_s"] = std::round(face_frames_per_s);
  out["us_per_face_frame"] = std::round(1e6 / face_frames_per_s * 100.0) / 100.0;
  out["cpu_us_per_face_frame"] = std::round(cpu_s / face_frames * 1e6 * 100.0) / 100.0;
  out["face_frames_per_cpu_s"] = std::round(face_frames / cpu_s);
  out["realtime_faces_at_rate"] = std::floor(face_frames_per_s / args.rate_hz);
  out["bytes_per_face"] = state_bytes + model_bytes;  // each avatar its own fitted model
  out["state_bytes_per_face"] = state_bytes;
  out["model_bytes"] = model_bytes;
  out["residual_rms_mm"] = std::round(residual_mean * 1000.0) / 1000.0;
  out["residual_rms_mm_max"] = std::round(double(residual_worst) * 1000.0) / 1000.0;
  out["goal_face_frames_per_s"] = kGoalFaceFramesPerS;
  out["goal_met"] = face_frames_per_s >= kGoalFaceFramesPerS && double(state_bytes + model_bytes) <= kGoalBytesPerFace;
  out["paper_face_frames_per_s"] = kPaperFaceFramesPerS;
  out["paper_bytes_per_face"] = kPaperBytesPerFace;
  if (args.json) {
    std::cout << out.dump() << "\n";
    return;
  }
  std::cout << "physics face, " << args.solver << ": " << out["nodes"] << " nodes, " << out["springs"] << " springs, "
            << out["muscles"] << " muscles, " << out["elements"] << " elements, " << out["substeps_per_frame"]
            << " sub-steps per frame\n"
            << args.faces << " faces on " << pool.thread_count() << " threads: " << out["face_frames_per_s"]
            << " face-frames/s (" << out["us_per_face_frame"] << " us each; goal " << kGoalFaceFramesPerS
            << "), " << out["bytes_per_face"] << " bytes per face, residual " << out["residual_rms_mm"]
            << " mm RMS (max " << out["residual_rms_mm_max"] << ")\n";
}

}  // namespace

void add_sim_bench(CLI::App& app) {
  auto args = std::make_shared<SimBenchArgs>();
  CLI::App* cmd = app.add_subcommand("sim", "Physics face: face-frames per second, bytes per face, residual");
  cmd->add_option("--faces", args->faces, "faces simulated together (1..100000)");
  cmd->add_option("--seconds", args->seconds, "simulated seconds");
  cmd->add_option("--threads", args->threads, "threads (0 = one per hardware thread)");
  cmd->add_option("--solver", args->solver, "massspring or pbd");
  cmd->add_option("--rate-hz", args->rate_hz, "rendered frames per simulated second");
  cmd->add_option("--seed", args->seed, "seed of the faces and their expression drive");
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
