#include "render_command.hpp"

#include <cmath>
#include <iostream>
#include <numbers>
#include <charconv>

#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/model/procedural_texture.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"
#include "fw/render/png.hpp"

namespace fw::client {
namespace {

struct RenderArgs {
  bool generic = false;
  std::string avatar;
  std::string output;
  std::string size = "512x512";
  double yaw_deg = 0, pitch_deg = 0, roll_deg = 0;
  int samples = 4;
};

[[noreturn]] void fail(int status, const std::string& message) {
  std::cerr << "facewire-client render: " << message << "\n";
  std::exit(status);
}

// Parses "WIDTHxHEIGHT"; false if it is not two whole numbers around an x.
bool parse_size(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string::npos) return false;
  const char* begin = text.data();
  const char* end = begin + text.size();
  const auto w = std::from_chars(begin, begin + x, width);
  const auto h = std::from_chars(begin + x + 1, end, height);
  return w.ec == std::errc() && w.ptr == begin + x && h.ec == std::errc() && h.ptr == end;
}

float radians(double degrees) { return static_cast<float>(degrees * std::numbers::pi / 180.0); }

// The face to draw: a prepared avatar, or the generic face with a procedural skin.
render::AvatarAppearance load_appearance(const RenderArgs& args) {
  render::AvatarAppearance appearance;
  std::string error;
  if (args.avatar.empty()) {
    const model::Appearance look;
    appearance.face = model::generic_face();
    appearance.textures = {model::make_skin_texture(appearance.face, look),
                           model::make_eye_texture(appearance.face.eyes[0], look), model::make_mouth_texture()};
    return appearance;
  }
  std::vector<std::uint8_t> bytes;
  model::AvatarPackage package;
  if (!model::read_file(args.avatar, model::kMaxPackageBytes, bytes, error)) fail(2, error);
  if (!model::parse_avatar_package(bytes, package, error)) fail(2, args.avatar + ": " + error);
  if (!render::load_avatar_appearance(package, appearance, error)) fail(2, args.avatar + ": " + error);
  return appearance;
}

void run(const RenderArgs& args) {
  if (!args.generic && args.avatar.empty())
    fail(2, "say what to render: --generic (the generic face) or --avatar NAME.fwa (a prepared avatar)");

  render::RendererOptions options;
  if (!parse_size(args.size, options.width, options.height))
    fail(2, "--size must look like 512x512 (width x height in pixels), not '" + args.size + "'");
  options.samples = args.samples;

  std::string error;
  auto renderer = render::FaceRenderer::create(options, error);
  if (!renderer) fail(2, error);

  const render::AvatarAppearance appearance = load_appearance(args);
  const render::FaceId id = renderer->add_face(appearance.face, appearance.textures);
  render::HeadPose pose;
  pose.yaw_rad = radians(args.yaw_deg);
  pose.pitch_rad = radians(args.pitch_deg);
  pose.roll_rad = radians(args.roll_deg);
  const render::FaceDraw draw{id, render::head_transform(pose), {}};
  const auto camera =
      render::Camera::portrait(static_cast<float>(options.width) / static_cast<float>(options.height));
  const model::RgbaImage image = renderer->render({&draw, 1}, camera);
  if (!render::write_png(image, args.output, error)) fail(2, error);
  std::cout << "wrote " << args.output << " (" << options.width << "x" << options.height << ")\n";
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a face to a PNG image");
  auto* source = cmd->add_flag("--generic", args->generic, "render the generic face with a procedural skin");
  cmd->add_option("--avatar", args->avatar, "render a prepared avatar package (.fwa)")->excludes(source);
  cmd->add_option("-o,--output", args->output, "PNG file to write")->required();
  cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT, 16..4096 each")->capture_default_str();
  cmd->add_option("--yaw", args->yaw_deg, "head yaw in degrees, + turns toward the face's left")
      ->check(CLI::Range(-70.0, 70.0));
  cmd->add_option("--pitch", args->pitch_deg, "head pitch in degrees, + looks up")->check(CLI::Range(-45.0, 45.0));
  cmd->add_option("--roll", args->roll_deg, "head roll in degrees, + tilts toward the face's left shoulder")
      ->check(CLI::Range(-35.0, 35.0));
  cmd->add_option("--samples", args->samples, "anti-aliasing samples (0 = off)")
      ->check(CLI::Range(0, 16))
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::client
