#include "fw/model/head_shell.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <type_traits>

#include <glm/geometric.hpp>

#include "fw/model/head_back.hpp"

namespace fw::model {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

// How one ray is stretched: within the generic rim in proportion to the
// fitted rim, beyond it from the fitted rim to the person's outline.
struct RayMap {
  float generic_rim, fitted_rim, generic_outline, fitted_outline;
  float operator()(float r) const {
    if (r <= generic_rim) return r * fitted_rim / generic_rim;
    return fitted_rim + (r - generic_rim) * (fitted_outline - fitted_rim) / (generic_outline - generic_rim);
  }
};

}  // namespace

std::vector<std::uint32_t> face_rim_loop(const Mesh& skin) {
  std::vector<std::uint32_t> longest;  // the eye holes and the mouth slit are short
  for (auto& loop : boundary_loops(skin))
    if (loop.size() > longest.size()) longest = std::move(loop);
  return longest;
}

float unseen_colour_radius(float phi, float rim, float outline) {
  if (std::sin(phi) < kNeckRaySine) return rim - 0.15f;
  // Deep enough inside that the colour is the person's: the last tenths of
  // a unit inside a photo's outline are often a pale fringe (wisps of hair
  // against the background, the matte's soft edge).
  return outline - 0.32f;
}

float outline_ray_angle(std::size_t k, std::size_t count) {
  return kTwoPi * static_cast<float>(k) / static_cast<float>(count);
}

namespace {

// Where the ray leaves the loop (its outermost crossing), and the loop's
// depth there (0 for a flat polygon).
template <typename Point>
RayExit exit_through(glm::vec2 centre, float phi, std::span<const Point> loop) {
  const glm::vec2 d(std::cos(phi), std::sin(phi));
  RayExit best;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Point& from = loop[i];
    const Point& to = loop[(i + 1) % loop.size()];
    const glm::vec2 a = glm::vec2(from) - centre, b = glm::vec2(to) - centre;
    const glm::vec2 e = b - a;
    const float denominator = d.x * e.y - d.y * e.x;
    if (std::abs(denominator) < 1e-9f) continue;
    const float t = (a.x * e.y - a.y * e.x) / denominator;   // along the ray
    const float s = (a.x * d.y - a.y * d.x) / denominator;   // along the edge
    if (t > 0 && s >= 0 && s <= 1 && t > best.radius) {
      best.radius = t;
      if constexpr (std::is_same_v<Point, glm::vec3>) best.depth = from.z + s * (to.z - from.z);
    }
  }
  return best;
}

}  // namespace

float ray_exit_radius(glm::vec2 centre, float phi, std::span<const glm::vec2> polygon) {
  return exit_through(centre, phi, polygon).radius;
}

RayExit ray_exit(glm::vec2 centre, float phi, std::span<const glm::vec3> loop) {
  return exit_through(centre, phi, loop);
}

namespace {

// Each ray's stretch, and where its hidden part takes its colour.
struct ShellRays {
  std::vector<RayMap> maps;
  std::vector<float> colour_radius;
};

ShellRays shell_rays(const GenericFace& generic, std::span<const glm::vec2> fitted_xy, std::span<const float> outline) {
  const HeadShell& shell = generic.head;
  const std::size_t count = shell.outline.size();
  assert(outline.empty() || outline.size() == count);
  std::vector<glm::vec2> generic_rim, fitted_rim;
  for (std::uint32_t v : face_rim_loop(generic.skin)) {
    generic_rim.emplace_back(generic.skin.positions[v]);
    fitted_rim.push_back(fitted_xy[v]);
  }
  ShellRays rays;
  for (std::size_t k = 0; k < count; ++k) {
    const float phi = outline_ray_angle(k, count);
    RayMap map{ray_exit_radius(shell.centre, phi, generic_rim), ray_exit_radius(shell.centre, phi, fitted_rim),
               shell.outline[k], 0.0f};
    if (!(map.generic_rim > 0) || !(map.fitted_rim > 0)) map.generic_rim = map.fitted_rim = 1.0f;  // unreachable
    const float wanted = outline.empty() ? map.generic_outline + map.fitted_rim - map.generic_rim : outline[k];
    map.fitted_outline = std::max(wanted, map.fitted_rim + kShellBeyondRim);
    rays.maps.push_back(map);
    // Colour from where the person is, even where the shell reaches past them.
    rays.colour_radius.push_back(unseen_colour_radius(phi, map.fitted_rim, wanted));
  }
  return rays;
}

}  // namespace

std::vector<float> unseen_colour_radii(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                                       std::span<const float> outline) {
  return shell_rays(generic, fitted_xy, outline).colour_radius;
}

HeadShell fit_head_shell(const GenericFace& generic, std::span<const glm::vec2> fitted_xy,
                         std::span<const float> outline) {
  const HeadShell& shell = generic.head;
  const std::size_t count = shell.outline.size();
  const ShellRays rays = shell_rays(generic, fitted_xy, outline);
  const std::vector<RayMap>& maps = rays.maps;
  const std::vector<float>& colour_radius = rays.colour_radius;
  // Every vertex lies on a ray (the poles at the centre, on all of them).
  const auto ray_of = [&](glm::vec2 d) {
    const float at = std::atan2(d.y, d.x) / kTwoPi * static_cast<float>(count);
    return static_cast<std::size_t>(std::lround(at < 0 ? at + static_cast<float>(count) : at)) % count;
  };
  const TextureFrame& frame = generic.texture_frame;
  HeadShell fitted = shell;
  for (std::size_t v = 0; v < shell.mesh.positions.size(); ++v) {
    const glm::vec2 p(shell.mesh.positions[v]);
    const glm::vec2 d = p - shell.centre;
    const float r = glm::length(d);
    const glm::vec2 moved = r < 1e-6f ? p : shell.centre + d * (maps[ray_of(d)](r) / r);
    fitted.mesh.positions[v].x = moved.x;
    fitted.mesh.positions[v].y = moved.y;
    // A vertex the photo shows has its own position as its uv; one behind
    // the silhouette keeps its place on the head's back (head_back.hpp);
    // the others, hidden behind the face, take their ray's colour, moved to
    // where the person's is.
    if (on_head_back_patch(shell.mesh.uvs[v])) continue;
    const glm::vec2 colour_point = frame.to_model(shell.mesh.uvs[v]);
    if (glm::length(colour_point - p) < 1e-3f) {
      fitted.mesh.uvs[v] = frame.to_uv(moved);
    } else {
      const std::size_t k = ray_of(colour_point - shell.centre);
      const float phi = outline_ray_angle(k, count);
      fitted.mesh.uvs[v] = frame.to_uv(shell.centre + colour_radius[k] * glm::vec2(std::cos(phi), std::sin(phi)));
    }
  }
  for (std::size_t k = 0; k < count; ++k) fitted.outline[k] = maps[k].fitted_outline;
  return fitted;
}

}  // namespace fw::model
