#include "physics_renders.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "fw/model/expressions.hpp"
#include "fw/model/face_reconstruction.hpp"
#include "fw/model/generic_face.hpp"
#include "fw/physics/face_simulation.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "fw/render/face_renderer.hpp"
#include "fw/render/png.hpp"
#include "bench_failure.hpp"
#include "kinematic_track.hpp"

namespace fw::bench {
namespace {

using AuTargets = std::array<float, codec::kAuChannelCount>;

constexpr double kFrameS = 1.0 / 30.0;
constexpr float kMmPerUnit = 63.0f;

struct Scenario {
  std::string name;
  codec::FaceParams targets;
};

std::vector<Scenario> scenarios() {
  Scenario disgust{"disgust", {}};
  model::apply_expression(model::Expression::disgust, 1.0f, disgust.targets);
  Scenario jaw{"wide_jaw", {}};
  for (const int au : {25, 27}) jaw.targets.set_au(au, 1.0f);  // lips apart, mouth stretch (AU 26 is the lesser drop)
  return {disgust, jaw};
}

double rms_mm(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += glm::dot(a[i] - b[i], a[i] - b[i]);
  return std::sqrt(sum / static_cast<double>(a.size())) * kMmPerUnit;
}

double max_mm(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  double most = 0;
  for (std::size_t i = 0; i < a.size(); ++i) most = std::max(most, static_cast<double>(glm::length(a[i] - b[i])));
  return most * kMmPerUnit;
}

struct Panels {
  model::FaceShape kinematic, streamed, simulated;
};

// The three faces of one moment: the kinematic fallback as a client
// rebuilds it, the physics face as a client rebuilds it from the stream
// (measured AU weights and corrective weights), and the simulated skin
// itself (with the streamed face's texture slides).
Panels panels_now(physics::FaceSimulation& sim, const AuTargets& kinematic, const model::AvatarModel& avatar) {
  const physics::FaceMeasurement m = sim.measure();
  codec::FaceParams kin, streamed;
  kin.au = kinematic;
  streamed.au = m.action_units;
  streamed.corrective = m.corrective;
  Panels p{model::reconstruct_face(avatar, kin), model::reconstruct_face(avatar, streamed), {}};
  p.simulated = p.streamed;
  p.simulated.positions = sim.surface();
  return p;
}

// Each panel is rendered alone by the same camera and the three are put
// side by side: faces placed in a row would each be seen from another angle.
void write_row(render::FaceRenderer& renderer, render::FaceId id, const Panels& panels, float yaw_rad,
               const std::filesystem::path& path) {
  codec::FaceParams pose;
  pose.head_yaw_rad = yaw_rad;
  model::RgbaImage row;
  int x0 = 0;
  for (const model::FaceShape* shape : {&panels.kinematic, &panels.streamed, &panels.simulated}) {
    renderer.set_face_shape(id, shape->positions, shape->uvs);
    const render::FaceDraw draw = render::face_draw(id, pose);
    const model::RgbaImage panel = renderer.render(std::span(&draw, 1), render::Camera::group(1, 1.0f));
    if (row.width == 0) row = model::RgbaImage(3 * panel.width, panel.height);
    for (int y = 0; y < panel.height; ++y)
      std::copy_n(panel.at(0, y), 4 * panel.width, row.at(x0, y));
    x0 += panel.width;
  }
  std::string error;
  if (!render::write_png(row, path, error)) fail_bench("physics-renders", error);
}

void run(const std::filesystem::path& out_dir, double onset_s, double settle_s) {
  std::filesystem::create_directories(out_dir);
  render::RendererOptions options;
  options.width = 400;
  options.height = 400;
  std::string error;
  auto renderer = render::FaceRenderer::create(options, error);
  if (!renderer) fail_bench("physics-renders", error);
  const model::GenericFace& face = model::generic_face();
  const render::AvatarAppearance appearance = render::generic_appearance(model::Appearance{});
  const render::FaceId id = renderer->add_face(face, appearance.textures);

  nlohmann::json out = {{"benchmark", "physics-renders"}, {"solver", "projective"}, {"out", out_dir.string()}};
  for (const Scenario& scenario : scenarios()) {
    physics::SimulationOptions o;
    o.solver = physics::Solver::projective;
    physics::FaceSimulation sim(face, o);
    sim.set_action_units(scenario.targets.au);
    KinematicTrack kinematic;
    double t = 0;
    for (const auto& [moment, until_s] : {std::pair{"onset", onset_s}, std::pair{"settled", settle_s}}) {
      for (; t + 1e-9 < until_s; t += kFrameS) {
        sim.step(kFrameS);
        kinematic.follow(scenario.targets.au, kFrameS);
      }
      const Panels p = panels_now(sim, kinematic.weights(), appearance.avatar);
      const std::string stem = scenario.name + "_" + moment;
      write_row(*renderer, id, p, 0.0f, out_dir / (stem + "_front.png"));
      write_row(*renderer, id, p, 0.7f, out_dir / (stem + "_side.png"));
      out[stem] = {{"t_s", std::round(t * 1000) / 1000},
                   {"kinematic_vs_streamed_rms_mm", rms_mm(p.kinematic.positions, p.streamed.positions)},
                   {"kinematic_vs_streamed_max_mm", max_mm(p.kinematic.positions, p.streamed.positions)},
                   {"streamed_vs_simulated_rms_mm", rms_mm(p.streamed.positions, p.simulated.positions)},
                   {"kinematic_vs_simulated_rms_mm", rms_mm(p.kinematic.positions, p.simulated.positions)},
                   {"kinematic_vs_simulated_max_mm", max_mm(p.kinematic.positions, p.simulated.positions)}};
    }
  }
  std::cout << out.dump() << "\n";
}

}  // namespace

void add_physics_renders(CLI::App& app) {
  auto dir = std::make_shared<std::string>("physics-renders");
  auto onset = std::make_shared<double>(0.1);
  auto settle = std::make_shared<double>(2.0);
  CLI::App* cmd = app.add_subcommand(
      "physics-renders",
      "Disgust and a wide jaw opening, kinematic | physics as streamed | simulated skin, side by side (PNGs), "
      "with their distances as JSON");
  cmd->add_option("--out", *dir, "folder for the PNGs")->capture_default_str();
  cmd->add_option("--onset", *onset, "seconds after the targets change for the first moment")
      ->check(CLI::Range(1.0 / 30, 5.0))
      ->capture_default_str();
  cmd->add_option("--settled", *settle, "seconds for the settled moment")->check(CLI::Range(0.1, 20.0))->capture_default_str();
  cmd->callback([dir, onset, settle] { run(*dir, *onset, std::max(*settle, *onset)); });
}

}  // namespace fw::bench
