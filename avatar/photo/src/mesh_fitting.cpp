#include "mesh_fitting.hpp"

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

#include "fw/model/face_asset.hpp"
#include "fw/model/fitted_face.hpp"

namespace fw::photo {
namespace {

// Inner lips closer than this (model units) are closed lips: the template's
// closed slit is 0.015 at the middle, dlib's points on closed lips lie a
// pixel or two apart or cross.
constexpr float kClosedLipGap = 0.02f;
// A little smoothing so one misplaced landmark bends the mesh gently.
constexpr float kRegularization = 1e-2f;

// Rounds of untangling allowed before a fold is reported.
constexpr int kMaxUntangleRounds = 50;

float signed_area(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return 0.5f * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// Where strongly different landmark moves meet (a broad smile, say), the
// spline can fold a triangle over. Moving the free corners of folded
// triangles to the mean of their neighbours, a few times, opens them again;
// landmark vertices stay where the landmarks are.
void untangle(const model::GenericFace& generic, std::vector<glm::vec2>& xy) {
  std::vector<std::set<std::uint32_t>> neighbours(xy.size());
  for (const glm::uvec3& t : generic.skin.triangles)
    for (int k = 0; k < 3; ++k) neighbours[t[k]].insert({t[(k + 1) % 3], t[(k + 2) % 3]});
  const std::set<std::uint32_t> anchored(generic.landmark_vertices.begin(), generic.landmark_vertices.end());
  for (int round = 0; round < kMaxUntangleRounds; ++round) {
    std::set<std::uint32_t> loose;
    for (const glm::uvec3& t : generic.skin.triangles)
      if (signed_area(xy[t.x], xy[t.y], xy[t.z]) < 1e-4f)
        for (int k = 0; k < 3; ++k)
          if (!anchored.contains(t[k])) loose.insert(t[k]);
    if (loose.empty()) return;
    for (std::uint32_t v : loose) {
      glm::vec2 mean(0.0f);
      for (std::uint32_t u : neighbours[v]) mean += xy[u];
      xy[v] = mean / static_cast<float>(neighbours[v].size());
    }
  }
}

}  // namespace

ModelLandmarks landmarks_for_fit(const ModelLandmarks& landmarks) {
  ModelLandmarks out = landmarks;
  for (const auto& [upper, lower] : {std::pair{61, 67}, {62, 66}, {63, 65}}) {
    glm::vec2& u = out[static_cast<std::size_t>(upper)];
    glm::vec2& l = out[static_cast<std::size_t>(lower)];
    // They meet: at rest nothing between them (the cavity, the photo's
    // teeth) shows. Their whole points meet, not just their heights, so the
    // upper lip's edge lies exactly on the lower's and no crack opens
    // between them.
    if (u.y - l.y < kClosedLipGap) u = l = 0.5f * (u + l);
  }
  return out;
}

namespace {

// The mesh through the spline that takes the template's landmarks to
// `target` at smoothing `lambda`, untangled and kept on the texture; nullopt
// if the spline is degenerate or a triangle stays folded.
std::optional<MeshFit> try_fit(const model::GenericFace& generic, const ModelLandmarks& target, float lambda,
                               std::string& problem) {
  MeshFit fit;
  if (!fit.warp.fit(model::landmark_template(), target, lambda)) {
    problem = "the landmarks are degenerate";
    return std::nullopt;
  }
  fit.fitted_xy.resize(generic.skin.positions.size());
  for (std::size_t v = 0; v < fit.fitted_xy.size(); ++v) fit.fitted_xy[v] = fit.warp(glm::vec2(generic.skin.positions[v]));
  for (int i = 0; i < model::kLandmarkCount; ++i)
    fit.fitted_xy[generic.landmark_vertices[static_cast<std::size_t>(i)]] = target[static_cast<std::size_t>(i)];

  untangle(generic, fit.fitted_xy);
  // The rim may be pushed past the texture's edge by a long or wide face;
  // keep it on the texture (it only carries hair and the sides of the head).
  const glm::vec2 low = generic.texture_frame.origin, high = low + generic.texture_frame.size;
  for (glm::vec2& p : fit.fitted_xy) p = glm::clamp(p, low + 0.01f, high - 0.01f);

  const auto problems = model::validate_generic_face(model::fit_generic_face(generic, fit.fitted_xy));
  if (!problems.empty()) {
    problem = problems.front();
    return std::nullopt;
  }
  return fit;
}

}  // namespace

MeshFit fit_mesh(const model::GenericFace& generic, const ModelLandmarks& raw, std::string& note) {
  const ModelLandmarks target = landmarks_for_fit(raw);
  std::string problem;
  // The spline through the landmarks as found, then smoother ones: where
  // landmarks crowd or cross (a misplaced lip point, a face half hidden),
  // smoothing lets the mesh pass near them without folding.
  for (const float lambda : {kRegularization, 0.1f, 1.0f})
    if (auto fit = try_fit(generic, target, lambda, problem)) {
      if (lambda != kRegularization) note = "the mesh was smoothed to fit (" + problem + " at first)";
      return *std::move(fit);
    }
  // Then landmarks drawn part of the way toward the template's, which fits
  // the generic face exactly: some of the face's own shape is given up, but
  // its texture (taken through the eyes' alignment, not the mesh) stays.
  const auto tmpl = model::landmark_template();
  for (const float keep : {0.75f, 0.5f, 0.25f, 0.0f}) {
    ModelLandmarks drawn{};
    for (std::size_t i = 0; i < drawn.size(); ++i) drawn[i] = tmpl[i] + keep * (target[i] - tmpl[i]);
    std::string later_problem;
    if (auto fit = try_fit(generic, drawn, 1.0f, later_problem)) {
      note = "the face's shape was drawn " + std::to_string(static_cast<int>(std::lround(100 * (1 - keep)))) +
             " % toward the generic face to fit (" + problem + " at first)";
      return *std::move(fit);
    }
  }
  // The template's own landmarks give the generic face, which the asset's
  // tests hold free of folds: not reached.
  throw std::logic_error("the generic face does not fit its own landmarks");
}

}  // namespace fw::photo
