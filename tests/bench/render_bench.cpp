#include "render_bench.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "fw/model/procedural_texture.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"

namespace fw::bench {
namespace {

struct RenderBenchArgs {
  double seconds = 3.0;
  int samples = 4;
  bool json = false;
};

struct Measured {
  double fps = 0;
  int frames = 0;
};

[[noreturn]] void fail(const std::string& message) {
  std::cerr << "facewire-bench render: " << message << "\n";
  std::exit(2);
}

// Renders `faces` heads that keep turning (so no frame repeats the last) for
// about `seconds`, and reports whole frames per second including read-back,
// which is what a client pays for every frame.
Measured measure(int width, int height, int faces, const RenderBenchArgs& args, std::string* renderer_name) {
  render::RendererOptions options;
  options.width = width;
  options.height = height;
  options.samples = args.samples;
  std::string error;
  auto renderer = render::FaceRenderer::create(options, error);
  if (!renderer) fail(error);
  if (renderer_name) *renderer_name = renderer->renderer_name();

  const model::GenericFace& face = model::generic_face();
  std::vector<render::FaceDraw> draws;
  for (int i = 0; i < faces; ++i) {
    model::Appearance look;
    look.skin *= 0.7f + 0.3f * static_cast<float>(i % 3) / 2.0f;
    const render::AvatarAppearance appearance = render::generic_appearance(look);
    const auto id = renderer->add_face(face, appearance.textures);
    draws.push_back({id, glm::mat4(1.0f), {}});
  }
  const auto camera = render::Camera::group(faces, static_cast<float>(width) / static_cast<float>(height));

  renderer->render(draws, camera);  // warm-up: shader compilation, first uploads
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  Measured m;
  double elapsed = 0;
  while (elapsed < args.seconds || m.frames < 3) {
    for (int i = 0; i < faces; ++i) {
      render::HeadPose pose;
      pose.yaw_rad = 0.4f * std::sin(0.1f * static_cast<float>(m.frames + 7 * i));
      pose.pitch_rad = 0.1f * std::cos(0.13f * static_cast<float>(m.frames + 3 * i));
      draws[static_cast<std::size_t>(i)].model = render::head_transform(pose, render::place_in_row(i, faces));
    }
    renderer->render(draws, camera);
    ++m.frames;
    elapsed = std::chrono::duration<double>(clock::now() - start).count();
  }
  m.fps = m.frames / elapsed;
  return m;
}

void run(const RenderBenchArgs& args) {
  std::string renderer_name;
  const Measured one = measure(256, 256, 1, args, &renderer_name);
  const Measured eight = measure(640, 480, 8, args, nullptr);
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
  if (args.json) {
    std::cout << out.dump() << "\n";
  } else {
    std::cout << "renderer " << renderer_name << "\n1 face 256x256:     " << out["fps_1face_256"] << " fps\n"
              << "8 faces 640x480:    " << out["fps_8faces_640x480"] << " fps\n";
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
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::bench
