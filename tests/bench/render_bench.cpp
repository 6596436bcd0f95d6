#include "render_bench.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "fw/model/expressions.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/procedural_texture.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"
#include "bench_failure.hpp"

namespace fw::bench {
namespace {

struct RenderBenchArgs {
  double seconds = 3.0;
  int samples = 4;
  bool json = false;
  bool profile = false;
};

struct Measured {
  double fps = 0;
  int frames = 0;
  render::FrameProfile profile;  // filled only when profiled
};

// Renders `faces` heads that keep turning and changing expression (so no
// frame repeats the last) for about `seconds`, and reports whole frames per
// second including each face's reconstruction and the read-back: what a
// client pays for every frame. `profiled`: each part of a frame timed
// apart (render::FrameProfile), the reconstruction and shape upload as
// "shape"; its frames are slower, so its rate is not reported.
Measured measure(int width, int height, int faces, const RenderBenchArgs& args, bool profiled,
                 std::string* renderer_name) {
  render::RendererOptions options;
  options.width = width;
  options.height = height;
  options.samples = args.samples;
  std::string error;
  auto renderer = render::FaceRenderer::create(options, error);
  if (!renderer) fail_bench("render", error);
  if (renderer_name) *renderer_name = renderer->renderer_name();

  const model::GenericFace& face = model::generic_face();
  std::vector<render::FaceDraw> draws;
  std::vector<render::AvatarAppearance> appearances;
  for (int i = 0; i < faces; ++i) {
    model::Appearance look;
    look.skin *= 0.7f + 0.3f * static_cast<float>(i % 3) / 2.0f;
    appearances.push_back(render::generic_appearance(look));
    const auto id = renderer->add_face(face, appearances.back().textures);
    draws.push_back({id, glm::mat4(1.0f), {}});
  }
  const auto camera = render::Camera::group(faces, static_cast<float>(width) / static_cast<float>(height));

  renderer->render(draws, camera);  // warm-up: shader compilation, first uploads
  using clock = std::chrono::steady_clock;
  Measured m;
  if (profiled) renderer->set_profile(&m.profile);
  const auto start = clock::now();
  double elapsed = 0;
  while (elapsed < args.seconds || m.frames < 3) {
    const auto shape_start = clock::now();
    for (int i = 0; i < faces; ++i) {
      const float t = static_cast<float>(m.frames + 7 * i);
      codec::FaceParams params;
      model::apply_expression(static_cast<model::Expression>(i % model::kExpressionCount), 0.5f + 0.5f * std::sin(0.05f * t), params);
      params.head_yaw_rad = 0.4f * std::sin(0.1f * t);
      params.head_pitch_rad = 0.1f * std::cos(0.13f * t);
      params.eye_left = params.eye_right = {0.2f * std::sin(0.07f * t), 0.0f};
      const auto& appearance = appearances[static_cast<std::size_t>(i)];
      const model::FaceShape shape = model::reconstruct_face(appearance.avatar, params);
      renderer->set_face_shape(draws[static_cast<std::size_t>(i)].face, shape.positions, shape.uvs);
      draws[static_cast<std::size_t>(i)] = render::face_draw(draws[static_cast<std::size_t>(i)].face, params,
                                                             render::place_in_row(i, faces));
    }
    if (profiled) m.profile.add("shape", "", std::chrono::duration<double>(clock::now() - shape_start).count());
    renderer->render(draws, camera);
    ++m.frames;
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  }
  m.fps = m.frames / elapsed;
  renderer->set_profile(nullptr);
  return m;
}

void run(const RenderBenchArgs& args) {
  std::string renderer_name;
  const Measured one = measure(256, 256, 1, args, false, &renderer_name);
  const Measured eight = measure(640, 480, 8, args, false, nullptr);
  nlohmann::json out = {
      {"benchmark", "render"},
      {"renderer", renderer_name},
      {"samples", args.samples},
      {"fps_1face_256", std::round(one.fps * 10) / 10},
      {"frames_1face_256", one.frames},
      {"fps_8faces_640x480", std::round(eight.fps * 10) / 10},
      {"frames_8faces_640x480", eight.frames},
      {"skin_triangles", model::generic_face().skin.triangles.size()},
      {"skin_vertices", model::generic_face().skin.positions.size()},
  };
  if (args.profile) {
    for (const auto& [key, width, height, faces] : {std::tuple{"profile_1face_256", 256, 256, 1},
                                                    std::tuple{"profile_8faces_640x480", 640, 480, 8}}) {
      const Measured profiled = measure(width, height, faces, args, true, nullptr);
      const auto rounded = [](std::map<std::string, double, std::less<>> ms) {
        for (auto& [name, value] : ms) value = std::round(value * 1000) / 1000;
        return ms;
      };
      out[key] = {{"frames", profiled.profile.frames},
                  {"parts_ms", rounded(profiled.profile.per_frame_ms(false))},
                  {"variants_ms", rounded(profiled.profile.per_frame_ms(true))}};
    }
  }
  if (args.json) {
    std::cout << out.dump() << "\n";
  } else {
    std::cout << "renderer " << renderer_name << "\n1 face 256x256:     " << out["fps_1face_256"] << " fps\n"
              << "8 faces 640x480:    " << out["fps_8faces_640x480"] << " fps\n";
    for (const char* key : {"profile_1face_256", "profile_8faces_640x480"})
      if (out.contains(key)) std::cout << key << " (ms a frame, each part waited for): " << out[key].dump() << "\n";
  }
}

}  // namespace

void add_render_bench(CLI::App& app) {
  auto args = std::make_shared<RenderBenchArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Frames per second of the OSMesa face renderer");
  cmd->add_option("--seconds", args->seconds, "time spent on each measurement")
      ->check(CLI::Range(0.05, 600.0))
      ->capture_default_str();
  cmd->add_option("--samples", args->samples, "anti-aliasing samples")->check(CLI::Range(0, 16))->capture_default_str();
  cmd->add_flag("--json", args->json, "print one JSON object");
  cmd->add_flag("--profile", args->profile,
                "also time each part of a frame and each shader variant (waiting for each part: slower frames), "
                "in milliseconds a frame");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
