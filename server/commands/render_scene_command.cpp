#include "render_scene_command.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

#include "fw/behavior/scene_file.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/landmark_template.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/camera.hpp"
#include "fw/render/face_renderer.hpp"
#include "fw/render/png.hpp"
#include "fw/render/y4m_writer.hpp"
#include "command_failure.hpp"

namespace fw::server {
namespace {

struct RenderSceneArgs {
  std::string scene;
  std::string out_dir;
  std::string y4m;
  std::string size = "960x540";
  int every = 1;
  double from_s = 0;
  double to_s = 1e9;
  std::string face;  ///< --face: one avatar alone (its index or name), "" for the whole room
};

bool parse_size(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string::npos) return false;
  const char* begin = text.data();
  const auto w = std::from_chars(begin, begin + x, width);
  const auto h = std::from_chars(begin + x + 1, begin + text.size(), height);
  return w.ec == std::errc() && w.ptr == begin + x && h.ec == std::errc() && h.ptr == begin + text.size();
}

// A different look per avatar, so a viewer tells them apart.
model::Appearance look(std::size_t i) {
  // Named fields, so that a field added to Appearance cannot take another's value.
  static const model::Appearance looks[] = {
      {.skin = {0.86f, 0.66f, 0.55f}, .hair = {0.23f, 0.15f, 0.09f}, .iris = {0.30f, 0.45f, 0.62f}, .lips = {0.72f, 0.38f, 0.38f}},
      {.skin = {0.62f, 0.44f, 0.33f}, .hair = {0.08f, 0.06f, 0.05f}, .iris = {0.28f, 0.18f, 0.10f}, .lips = {0.58f, 0.30f, 0.28f}},
      {.skin = {0.93f, 0.78f, 0.68f}, .hair = {0.72f, 0.52f, 0.25f}, .iris = {0.35f, 0.55f, 0.35f}, .lips = {0.80f, 0.45f, 0.45f}},
      {.skin = {0.45f, 0.30f, 0.22f}, .hair = {0.05f, 0.04f, 0.04f}, .iris = {0.20f, 0.12f, 0.07f}, .lips = {0.45f, 0.24f, 0.22f}},
      {.skin = {0.80f, 0.60f, 0.45f}, .hair = {0.45f, 0.20f, 0.10f}, .iris = {0.40f, 0.40f, 0.30f}, .lips = {0.70f, 0.36f, 0.34f}},
  };
  model::Appearance a = looks[i % std::size(looks)];
  if (i >= std::size(looks)) a.hair *= 0.8f;  // beyond the palette: vary the hair
  return a;
}

// Frames every seat: the heads' extent across and the nearest one in depth.
render::Camera frame_seats(const behavior::Scene& scene, float aspect) {
  render::Camera camera = render::Camera::portrait(aspect);
  float lo = 1e9f, hi = -1e9f, front = -1e9f;
  for (const behavior::SceneAvatar& a : scene.avatars) {
    const glm::vec3 o = a.seat.value_or(behavior::Seat{}).origin_mm / model::kMillimetresPerUnit;
    lo = std::min(lo, o.x - 1.7f);
    hi = std::max(hi, o.x + 1.7f);
    front = std::max(front, o.z);
  }
  const float half_tan = std::tan(camera.fov_y_rad / 2);
  const float for_width = (hi - lo) / (2 * half_tan * aspect);
  const float for_height = 4.6f / (2 * half_tan);
  const float cx = 0.5f * (lo + hi);
  camera.target = {cx, -0.25f, front - 1.0f};
  camera.position = {cx, 0.2f, front + 2.2f + std::max(for_width, for_height)};
  return camera;
}

/// The frame size from --size: even, 16 to 4096 pixels each way.
std::pair<int, int> frame_size(const RenderSceneArgs& args) {
  int width = 0, height = 0;
  if (!parse_size(args.size, width, height) || width < 16 || height < 16 || width > 4096 || height > 4096 ||
      width % 2 || height % 2)
    fail_command("render-scene", "--size must look like 960x540 (even width x height, 16 to 4096 pixels), not '" + args.size + "'");
  return {width, height};
}

/// The scene, with every avatar seated (a version 1 scene has no seats: the
/// centre-facing arc it was recorded on, behavior::scene_seat).
behavior::Scene seated_scene(const std::string& path) {
  behavior::Scene scene;
  std::string error;
  if (!behavior::read_scene(path, scene, error)) fail_command("render-scene", error);
  for (std::size_t i = 0; i < scene.avatars.size(); ++i) scene.avatars[i].seat = behavior::scene_seat(scene, i);
  return scene;
}

/// The renderer with one face per avatar of the scene, each with its own look.
struct Cast {
  std::unique_ptr<render::FaceRenderer> renderer;
  std::vector<render::AvatarAppearance> appearances;
  std::vector<render::FaceId> ids;
};

Cast cast_for(const behavior::Scene& scene, int width, int height) {
  render::RendererOptions options;
  options.width = width;
  options.height = height;
  std::string error;
  Cast cast;
  cast.renderer = render::FaceRenderer::create(options, error);
  if (!cast.renderer) fail_command("render-scene", error);
  for (std::size_t i = 0; i < scene.avatars.size(); ++i) {
    cast.appearances.push_back(render::generic_appearance(look(i)));
    cast.ids.push_back(cast.renderer->add_face(cast.appearances.back().avatar.face, cast.appearances.back().textures));
  }
  return cast;
}

/// --face: the index of the avatar its value names (a number below the
/// avatar count, or a name in the scene), or a failure that lists them.
std::size_t chosen_face(const behavior::Scene& scene, const std::string& face) {
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(face.data(), face.data() + face.size(), index);
  if (ec == std::errc() && end == face.data() + face.size() && index < scene.avatars.size()) return index;
  for (std::size_t i = 0; i < scene.avatars.size(); ++i)
    if (scene.avatars[i].name == face) return i;
  std::string names;
  for (std::size_t i = 0; i < scene.avatars.size(); ++i)
    names += (i ? ", " : "") + std::to_string(i) + " " + scene.avatars[i].name;
  fail_command("render-scene", "--face " + face + " is not an avatar of the scene; give its number or name (" + names + ")");
}

/// Avatar `i` at tick `t`, shaped, for a draw at `place`.
render::FaceDraw shaped(Cast& cast, const behavior::Scene& scene, std::size_t i, std::size_t t, const glm::mat4& place) {
  const codec::FaceParams& params = scene.avatars[i].ticks[t];
  const model::FaceShape shape = model::reconstruct_face(cast.appearances[i].avatar, params);
  cast.renderer->set_face_shape(cast.ids[i], shape.positions, shape.uvs);
  return render::face_draw(cast.ids[i], params, place);
}

/// Where a face rendered alone is put: turned so that the camera sits where
/// its head points on average over ticks [first, last). Its head and eyes
/// then move as in the room, toward partners the picture does not show,
/// and the face is seen from the front rather than in the profile its
/// seat would give whenever it attends someone beside it.
glm::mat4 facing_the_camera(const behavior::SceneAvatar& avatar, std::size_t first, std::size_t last) {
  double yaw = 0;
  std::size_t ticks = 0;
  for (std::size_t t = first; t < last && t < avatar.ticks.size(); ++t)
    if (avatar.present(t)) {
      yaw += avatar.ticks[t].head_yaw_rad;
      ++ticks;
    }
  const auto mean = static_cast<float>(ticks ? yaw / static_cast<double>(ticks) : 0.0);
  return glm::rotate(glm::mat4(1.0f), -mean, glm::vec3(0, 1, 0));
}

/// Every avatar present at tick `t`, shaped and placed in its seat; or,
/// with `alone`, that avatar only, placed by `alone_place`.
model::RgbaImage render_tick(Cast& cast, const behavior::Scene& scene, std::size_t t, const render::Camera& camera,
                             std::optional<std::size_t> alone, const glm::mat4& alone_place) {
  std::vector<render::FaceDraw> draws;
  if (alone) {
    if (scene.avatars[*alone].present(t)) draws.push_back(shaped(cast, scene, *alone, t, alone_place));
    return cast.renderer->render(draws, camera);
  }
  for (std::size_t i = 0; i < scene.avatars.size(); ++i) {
    const behavior::SceneAvatar& a = scene.avatars[i];
    if (!a.present(t)) continue;
    // The seat, as behavior::seat_layout.hpp defines it for the renderer.
    const glm::mat4 place = glm::rotate(glm::translate(glm::mat4(1.0f), a.seat->origin_mm / model::kMillimetresPerUnit),
                                        a.seat->facing_yaw_rad, glm::vec3(0, 1, 0));
    draws.push_back(shaped(cast, scene, i, t, place));
  }
  return cast.renderer->render(draws, camera);
}

/// Where the frames go: a Y4M stream, or numbered PNG files in a directory.
class FrameOutput {
 public:
  FrameOutput(const RenderSceneArgs& args, int width, int height, int fps) : out_dir_(args.out_dir) {
    if (args.y4m.empty()) {
      std::filesystem::create_directories(out_dir_);
      return;
    }
    std::string error;
    y4m_ = render::Y4mWriter::create(args.y4m, width, height, fps, error);
    if (!y4m_) fail_command("render-scene", error);
  }
  void write(const model::RgbaImage& image) {
    std::string error;
    if (y4m_) {
      if (!y4m_->write(image, error)) fail_command("render-scene", error);
    } else {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%06zu.png", frames_);
      if (!render::write_png(image, std::filesystem::path(out_dir_) / name, error)) fail_command("render-scene", error);
    }
    ++frames_;
  }
  std::size_t frames() const { return frames_; }

 private:
  std::string out_dir_;
  std::unique_ptr<render::Y4mWriter> y4m_;
  std::size_t frames_ = 0;
};

void run(const RenderSceneArgs& args) {
  if (args.out_dir.empty() == args.y4m.empty()) fail_command("render-scene", "give --out DIR for PNG frames or --y4m FILE (- for stdout), one of them");
  const auto [width, height] = frame_size(args);
  const behavior::Scene scene = seated_scene(args.scene);
  Cast cast = cast_for(scene, width, height);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const int fps = std::max(1, static_cast<int>(std::lround(static_cast<double>(scene.fps) / args.every)));
  FrameOutput output(args, width, height, fps);
  const auto first = static_cast<std::size_t>(std::max(0.0, args.from_s) * scene.fps);
  const auto last = std::min(scene.tick_count(), static_cast<std::size_t>(std::min(args.to_s, 1e7) * scene.fps));
  std::optional<std::size_t> alone;
  glm::mat4 alone_place(1.0f);
  render::Camera camera = frame_seats(scene, aspect);
  if (!args.face.empty()) {
    alone = chosen_face(scene, args.face);
    alone_place = facing_the_camera(scene.avatars[*alone], first, last);
    camera = render::Camera::portrait(aspect);
    camera.position.z *= 1.15f;  // room for the head's sway and turns around the neck
  }
  for (std::size_t t = first; t < last; t += static_cast<std::size_t>(args.every))
    output.write(render_tick(cast, scene, t, camera, alone, alone_place));
  std::cerr << "facewire-server render-scene: " << output.frames() << " frames of "
            << (alone ? "'" + scene.avatars[*alone].name + "' alone" : std::to_string(scene.avatars.size()) + " faces")
            << " at " << fps << " fps\n";
}

}  // namespace

void add_render_scene_command(CLI::App& app) {
  auto args = std::make_shared<RenderSceneArgs>();
  CLI::App* cmd = app.add_subcommand("render-scene", "Render a recorded room scene (.fws) to PNG frames or a Y4M video");
  cmd->add_option("scene", args->scene, "scene file from facewire-server simulate")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out_dir, "directory for frame_000000.png ...");
  cmd->add_option("--y4m", args->y4m, "Y4M video file, or - for stdout (| ffplay -)");
  cmd->add_option("--size", args->size, "WIDTHxHEIGHT in pixels, both even")->capture_default_str();
  cmd->add_option("--every", args->every, "render every Nth tick")->check(CLI::Range(1, 1000))->capture_default_str();
  cmd->add_option("--from", args->from_s, "start at this second")->check(CLI::NonNegativeNumber);
  cmd->add_option("--to", args->to_s, "stop at this second")->check(CLI::NonNegativeNumber);
  cmd->add_option("--face", args->face,
                  "render one avatar alone, facing the camera: its number (0 = the first to join) or name");
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::server
