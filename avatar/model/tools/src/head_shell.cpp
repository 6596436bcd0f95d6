#include "head_shell.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "fw/model/depth_profile.hpp"
#include "fw/model/head_back.hpp"
#include "fw/model/head_shell.hpp"

namespace fw::facegen {
namespace {

using model::HeadShell;

constexpr float kPi = std::numbers::pi_v<float>;
// Rays from the centre: N around the view axis (the outline's angles) by
// kRaysFrontToBack steps from the front pole to the back one.
constexpr int kRaysAround = 32;
constexpr int kRaysFrontToBack = 14;
// The point every ray starts from; its x and y are the outline's centre.
// It lies inside the shell's solid (behind the face's front limit), so that
// every ray leaves the solid at a point of its own.
constexpr glm::vec3 kCentre(0.0f, -0.2f, 0.2f);

struct Ellipsoid {
  glm::vec3 centre, radii;
  bool contains(glm::vec3 p) const {
    const glm::vec3 d = (p - centre) / radii;
    return glm::dot(d, d) <= 1.0f;
  }
};

// The head as a union of simple solids, model units (one unit 63 mm).
bool inside_head(glm::vec3 p) {
  static const Ellipsoid parts[] = {
      {{0.0f, 0.45f, 0.2f}, {1.42f, 1.6f, 1.6f}},     // cranium and hair: 200 mm long, 180 wide
      {{0.0f, -0.8f, 0.35f}, {1.4f, 1.2f, 1.3f}},     // cheeks and jaw
      {{0.0f, -1.55f, 0.95f}, {0.85f, 0.65f, 0.65f}},  // chin and the floor of the mouth
      {{-1.3f, -0.25f, 0.05f}, {0.24f, 0.5f, 0.32f}},  // ears
      {{1.3f, -0.25f, 0.05f}, {0.24f, 0.5f, 0.32f}},
  };
  for (const Ellipsoid& e : parts)
    if (e.contains(p)) return true;
  // The neck: an elliptic cylinder a little behind the head's middle, down
  // out of any frame.
  const glm::vec2 across(p.x / 0.82f, (p.z + 0.15f) / 0.85f);
  return p.y < -0.6f && p.y > -4.6f && glm::dot(across, across) <= 1.0f;
}

// Where the face's footprint (an ellipse about its rim, at 1) begins to be
// deep, and where the shell is left open behind it.
constexpr float kDeepFootprint = 0.92f, kHiddenFootprint = 0.9f;

// Within the face mesh's footprint the shell stays behind the face: 0.3 units
// behind its surface under the rim (which is set back 0.25), much deeper
// inside, so that neither the eyeballs nor the mouth cavity behind the face's
// holes ever meet it. Just beyond the rim the limit comes forward quickly,
// so that the ears, beside a face whose depth falls away toward them, keep
// their width.
float front_limit(glm::vec2 p) {
  const glm::vec2 q(p.x / 1.38f, (p.y + 0.24f) / 1.84f);
  const float e = glm::length(q);  // about 1 on the face's rim
  const float deep = std::clamp((kDeepFootprint - e) / 0.22f, 0.0f, 1.0f);
  const float beyond = std::max(0.0f, e - 1.0f);
  return model::face_depth(p) - 0.3f - 1.0f * deep * deep * (3.0f - 2.0f * deep) + 10.0f * beyond;
}

// The shell's solid: the head, cut back wherever it would come near the face.
bool inside_shell(glm::vec3 p) { return inside_head(p) && p.z <= front_limit(glm::vec2(p)); }

// The farthest point of the shell's solid along a ray from the centre. Every
// vertex on its own ray keeps the surface star-shaped about the centre, so
// its triangles all face outward: the renderer may cull the far side.
float shell_radius(glm::vec3 direction) {
  constexpr float kFar = 5.5f, kStep = 0.01f;
  float t = kFar;
  while (t > 0 && !inside_shell(kCentre + t * direction)) t -= kStep;
  float inside = t, outside = t + kStep;
  for (int i = 0; i < 20; ++i) {
    const float middle = 0.5f * (inside + outside);
    (inside_shell(kCentre + middle * direction) ? inside : outside) = middle;
  }
  return inside;
}

// Deep behind the face, where no view reaches past the face's skin, eyes
// and mouth (but for a pixel through closed lips seen steeply from below):
// the part of the shell cut flat by the front limit well inside the face's
// footprint. The shell leaves it open, since a software renderer pays for
// every sample even of what the depth test then hides.
bool hidden_behind_face(glm::vec3 p) {
  const bool on_the_cut = p.z > front_limit(glm::vec2(p)) - 0.01f;
  return on_the_cut && glm::length(glm::vec2(p.x / 1.38f, (p.y + 0.24f) / 1.84f)) < kHiddenFootprint;
}

// Where a point of the shell takes its colour on the head's back: its
// direction around the head, and how far it lies from the back pole toward
// the side (a quarter turn about the centre).
glm::vec2 head_back_uv(glm::vec3 p) {
  const glm::vec3 d = p - kCentre;
  const float from_back = std::acos(std::clamp(-d.z / glm::length(d), -1.0f, 1.0f));
  return model::head_back_uv(std::atan2(d.y, d.x), from_back / (0.5f * kPi));
}

// A triangle with a corner behind the silhouette takes all its colour from
// the head's back: one spanning the silhouette would otherwise stretch the
// texture between the photo and the disc across the whole texture. Its
// other corners get a copy of their own, at the same place, with a uv on
// the disc (a texture seam along the silhouette).
void use_head_back_across_silhouette(model::Mesh& mesh, std::size_t vertex_count) {
  std::vector<std::uint32_t> copy_of(vertex_count, 0);
  for (glm::uvec3& triangle : mesh.triangles) {
    bool behind = false;
    for (int c = 0; c < 3; ++c) behind = behind || model::on_head_back_patch(mesh.uvs[triangle[c]]);
    if (!behind) continue;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t v = triangle[c];
      if (model::on_head_back_patch(mesh.uvs[v])) continue;
      if (copy_of[v] == 0) {
        copy_of[v] = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(mesh.positions[v]);
        mesh.uvs.push_back(head_back_uv(mesh.positions[v]));
      }
      triangle[c] = copy_of[v];
    }
  }
}

// How far behind the face's rim the shell passes (model units): just enough
// that depth testing always keeps the face in front where they meet.
constexpr float kRimGap = 0.02f;

// Moves the ring point of one ray nearest the face's rim onto the rim, just
// behind it, so that the shell meets the face along its whole rim. Left
// where the rays happen to put them, the shell's coarse triangles crossed
// the rim: in front of the face's rim at the temples and cheeks (a second
// outline across a turned face), and up to 0.5 units behind it under the
// jaw (the face's jaw stood off the neck, a doubled jaw line). Returns the
// index of the point moved, or none.
std::optional<std::size_t> meet_the_rim(std::vector<glm::vec3>& ray, glm::vec2 centre, model::RayExit rim,
                                        std::size_t silhouette) {
  if (!(rim.radius > 0)) return std::nullopt;
  const auto radius = [&](std::size_t i) { return glm::length(glm::vec2(ray[i]) - centre); };
  // The ray's last point inside the rim and its first beyond: the nearer of
  // the two moves, if the points on either side of it then still run
  // outward through the rim (so the move folds no triangle).
  std::size_t beyond = 1;
  while (beyond < silhouette && radius(beyond) < rim.radius) ++beyond;
  const auto movable = [&](std::size_t i) {
    return i > 0 && i < silhouette && radius(i - 1) < rim.radius && radius(i + 1) > rim.radius;
  };
  std::size_t chosen = rim.radius - radius(beyond - 1) < radius(beyond) - rim.radius ? beyond - 1 : beyond;
  if (!movable(chosen)) chosen = chosen == beyond ? beyond - 1 : beyond;
  if (!movable(chosen)) return std::nullopt;
  const glm::vec2 d = glm::normalize(glm::vec2(ray[chosen]) - centre);
  ray[chosen] = glm::vec3(centre + rim.radius * d, rim.depth - kRimGap);
  return chosen;
}

glm::vec3 ray_direction(int ring, int segment) {
  const float theta = kPi * static_cast<float>(ring) / kRaysFrontToBack;
  const float phi = 2.0f * kPi * static_cast<float>(segment) / kRaysAround;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

HeadShell build_head_shell(const model::Mesh& skin, const model::TextureFrame& frame) {
  HeadShell shell;
  shell.centre = glm::vec2(kCentre);
  model::Mesh& mesh = shell.mesh;

  // Ring points of every segment, front to back (ring 0, the front pole, and
  // ring kRaysFrontToBack, the back pole, are added separately).
  std::vector<std::vector<glm::vec3>> rays(kRaysAround);
  for (int s = 0; s < kRaysAround; ++s)
    for (int ring = 1; ring < kRaysFrontToBack; ++ring) {
      const glm::vec3 d = ray_direction(ring, s);
      rays[static_cast<std::size_t>(s)].push_back(kCentre + shell_radius(d) * d);
    }

  std::vector<glm::vec3> rim;
  for (std::uint32_t v : model::face_rim_loop(skin)) rim.push_back(skin.positions[v]);

  std::vector<int> rim_ring(kRaysAround, -1);  // each ray's ring on the face's rim, -1 for none
  mesh.positions.push_back(kCentre + shell_radius({0, 0, 1}) * glm::vec3(0, 0, 1));
  mesh.uvs.push_back(frame.to_uv(shell.centre));
  for (int s = 0; s < kRaysAround; ++s) {
    auto& ray = rays[static_cast<std::size_t>(s)];
    // The silhouette seen from the front: the ring point farthest out. The
    // photo shows the ray from the face's rim up to it; what is hidden behind
    // the face takes the ray's colour from nearer the centre.
    std::size_t silhouette = 0;
    for (std::size_t i = 0; i < ray.size(); ++i)
      if (glm::length(glm::vec2(ray[i]) - shell.centre) > glm::length(glm::vec2(ray[silhouette]) - shell.centre))
        silhouette = i;
    const float phi = model::outline_ray_angle(static_cast<std::size_t>(s), kRaysAround);
    const model::RayExit crossing = model::ray_exit(shell.centre, phi, rim);
    const auto on_rim = meet_the_rim(ray, shell.centre, crossing, silhouette);
    rim_ring[static_cast<std::size_t>(s)] = on_rim ? static_cast<int>(*on_rim) + 1 : -1;
    const float radius = glm::length(glm::vec2(ray[silhouette]) - shell.centre);
    shell.outline.push_back(radius);
    const glm::vec2 unseen_colour = shell.centre + model::unseen_colour_radius(phi, crossing.radius, radius) *
                                                        glm::vec2(std::cos(phi), std::sin(phi));
    for (std::size_t i = 0; i < ray.size(); ++i) {
      const glm::vec2 p(ray[i]);
      const bool seen = glm::length(p - shell.centre) >= crossing.radius - 1e-4f;  // the point on the rim too
      mesh.positions.push_back(ray[i]);
      // Behind the silhouette: the head's back (head_back.hpp).
      mesh.uvs.push_back(i > silhouette ? head_back_uv(ray[i]) : frame.to_uv(seen ? p : unseen_colour));
    }
  }
  // The back pole, at the centre of the head's back.
  const glm::vec3 back_pole = kCentre - shell_radius({0, 0, -1}) * glm::vec3(0, 0, 1);
  const auto back_pole_index = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(back_pole);
  mesh.uvs.push_back(head_back_uv(back_pole));
  const std::size_t vertices_before_copies = mesh.positions.size();

  const auto at = [](int ring, int s) {  // ring 1..kRaysFrontToBack-1
    return static_cast<std::uint32_t>(1 + (s % kRaysAround) * (kRaysFrontToBack - 1) + (ring - 1));
  };
  // Counter-clockwise seen from outside: outward normals.
  const auto add = [&mesh](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const auto hidden = [&mesh](std::uint32_t v) { return hidden_behind_face(mesh.positions[v]); };
    if (!(hidden(a) && hidden(b) && hidden(c))) mesh.triangles.emplace_back(a, b, c);
  };
  for (int s = 0; s < kRaysAround; ++s) {
    add(0u, at(1, s), at(1, s + 1));
    const int next = (s + 1) % kRaysAround;
    for (int ring = 1; ring + 1 < kRaysFrontToBack; ++ring) {
      // Split each quad along the rim where the rim crosses it, so that the
      // rim is an edge of the shell and no triangle reaches across it.
      if (rim_ring[static_cast<std::size_t>(s)] == ring + 1 && rim_ring[static_cast<std::size_t>(next)] == ring) {
        add(at(ring, s), at(ring + 1, s), at(ring, s + 1));
        add(at(ring + 1, s), at(ring + 1, s + 1), at(ring, s + 1));
        continue;
      }
      add(at(ring, s), at(ring + 1, s), at(ring + 1, s + 1));
      add(at(ring, s), at(ring + 1, s + 1), at(ring, s + 1));
    }
    mesh.triangles.emplace_back(at(kRaysFrontToBack - 1, s), back_pole_index, at(kRaysFrontToBack - 1, s + 1));
  }
  use_head_back_across_silhouette(mesh, vertices_before_copies);
  return shell;
}

}  // namespace fw::facegen
