#include "render_command.hpp"

#include <charconv>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>

#include "face_options.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/file_io.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/contact_sheet.hpp"
#include "fw/render/face_renderer.hpp"
#include "fw/render/png.hpp"
#include "command_failure.hpp"

namespace fw::client {
namespace {

struct RenderArgs {
  bool generic = false;
  std::string avatar;
  std::string output;
  std::string size = "512x512";
  std::vector<std::string> emotions, action_units, blush;
  std::string gaze, head, lids;
  std::optional<double> yaw_deg, pitch_deg, roll_deg;
  double pallor = 0;
  bool sheet = false;
  int samples = 4;
};

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
  if (args.avatar.empty()) return render::generic_appearance(model::Appearance{});
  std::vector<std::uint8_t> bytes;
  model::AvatarPackage package;
  if (!model::read_file(args.avatar, model::kMaxPackageBytes, bytes, error)) fail_command("render", 2, error);
  if (!model::parse_avatar_package(bytes, package, error)) fail_command("render", 2, args.avatar + ": " + error);
  if (!render::load_avatar_appearance(package, appearance, error)) fail_command("render", 2, args.avatar + ": " + error);
  return appearance;
}

// Reads an optional "A,B[,C]" flag in degrees (or plain numbers) into `out`.
template <std::size_t N>
bool read_tuple(const std::string& text, const char* flag, std::array<double, N>& out, double limit) {
  if (text.empty()) return false;
  std::vector<double> values(N);
  std::string error;
  if (!parse_numbers(text, values, error)) fail_command("render", 2, std::string(flag) + ": " + error);
  for (std::size_t i = 0; i < N; ++i) {
    if (std::abs(values[i]) > limit) fail_command("render", 2, std::string(flag) + ": " + std::to_string(values[i]) + " is beyond +-" + std::to_string(static_cast<int>(limit)));
    out[i] = values[i];
  }
  return true;
}

codec::FaceParams face_params(const RenderArgs& args) {
  codec::FaceParams params;
  std::string error;
  if (!apply_emotions(args.emotions, params, error) || !apply_action_units(args.action_units, params, error) ||
      !apply_blush(args.blush, params, error))
    fail_command("render", 2, error);
  if (std::array<double, 2> g{}; read_tuple(args.gaze, "--gaze", g, 35.0))
    params.eye_left = params.eye_right = {radians(g[0]), radians(g[1])};
  if (std::array<double, 3> h{}; read_tuple(args.head, "--head", h, 70.0)) {
    params.head_yaw_rad = radians(h[0]);
    params.head_pitch_rad = radians(h[1]);
    params.head_roll_rad = radians(h[2]);
  }
  if (args.yaw_deg) params.head_yaw_rad = radians(*args.yaw_deg);
  if (args.pitch_deg) params.head_pitch_rad = radians(*args.pitch_deg);
  if (args.roll_deg) params.head_roll_rad = radians(*args.roll_deg);
  if (std::array<double, 2> l{}; read_tuple(args.lids, "--lids", l, 1.0)) {
    if (l[0] < 0 || l[1] < 0) fail_command("render", 2, "--lids: closures run from 0 (open) to 1 (closed)");
    params.lid_left = static_cast<float>(l[0]);
    params.lid_right = static_cast<float>(l[1]);
  }
  params.pallor = static_cast<float>(args.pallor);
  return params;
}

void run(const RenderArgs& args) {
  if (!args.generic && args.avatar.empty())
    fail_command("render", 2, "say what to render: --generic (the generic face) or --avatar NAME.fwa (a prepared avatar)");
  render::RendererOptions options;
  if (!parse_size(args.size, options.width, options.height))
    fail_command("render", 2, "--size must look like 512x512 (width x height in pixels), not '" + args.size + "'");
  options.samples = args.samples;
  const codec::FaceParams params = face_params(args);
  const render::AvatarAppearance appearance = load_appearance(args);

  std::string error;
  model::RgbaImage image;
  if (args.sheet) {
    // Panels as tall as the requested height, five to a row.
    if (!render::render_contact_sheet(appearance, options.height, render::kSheetColumns, image, error)) fail_command("render", 2, error);
  } else {
    auto renderer = render::FaceRenderer::create(options, error);
    if (!renderer) fail_command("render", 2, error);
    const render::FaceId id = renderer->add_face(appearance.avatar.face, appearance.textures);
    const model::FaceShape shape = model::reconstruct_face(appearance.avatar, params);
    renderer->set_face_shape(id, shape.positions, shape.uvs);
    const render::FaceDraw draw = render::face_draw(id, params);
    const auto camera =
        render::Camera::portrait(static_cast<float>(options.width) / static_cast<float>(options.height));
    image = renderer->render({&draw, 1}, camera);
  }
  if (!render::write_png(image, args.output, error)) fail_command("render", 2, error);
  std::cout << "wrote " << args.output << " (" << image.width << "x" << image.height << ")\n";
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a face to a PNG image");
  auto* source = cmd->add_flag("--generic", args->generic, "render the generic face with a procedural skin");
  cmd->add_option("--avatar", args->avatar, "render a prepared avatar package (.fwa)")->excludes(source);
  cmd->add_option("-o,--output", args->output, "PNG file to write")->required();
  cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT, 16..4096 each (with --sheet: HEIGHT is the panel size)")
      ->capture_default_str();
  cmd->add_option("--emotion", args->emotions, "NAME=INTENSITY: joy, sadness, anger, fear, surprise, disgust, cunning, teasing");
  cmd->add_option("--au", args->action_units, "N=V: a FACS action unit (1 2 4 5 6 7 9 10 12 14 15 17 20 23 24 25 26 27), "
                                              "N with L or R for one side, V 0..1");
  cmd->add_option("--gaze", args->gaze, "YAW,PITCH of both eyes in degrees; + looks to the face's left and up");
  auto* head = cmd->add_option("--head", args->head,
                               "YAW,PITCH,ROLL in degrees; + turns to the face's left, looks up, tilts to its left");
  cmd->add_option("--yaw", args->yaw_deg, "head yaw alone, degrees")->check(CLI::Range(-70.0, 70.0))->excludes(head);
  cmd->add_option("--pitch", args->pitch_deg, "head pitch alone, degrees")->check(CLI::Range(-45.0, 45.0))->excludes(head);
  cmd->add_option("--roll", args->roll_deg, "head roll alone, degrees")->check(CLI::Range(-35.0, 35.0))->excludes(head);
  cmd->add_option("--lids", args->lids, "L,R lid closure of the face's left and right eye, 0 open .. 1 closed");
  cmd->add_option("--blush", args->blush, "REGION=V: forehead, cheek_left, cheek_right, cheeks, nose, sides; V 0..1");
  cmd->add_option("--pallor", args->pallor, "whole-face pallor 0..1")->check(CLI::Range(0.0, 1.0));
  cmd->add_flag("--sheet", args->sheet, "a contact sheet: neutral, every expression, gaze, blink, blush, pallor");
  cmd->add_option("--samples", args->samples, "anti-aliasing samples (0 = off)")
      ->check(CLI::Range(0, 16))
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::client
