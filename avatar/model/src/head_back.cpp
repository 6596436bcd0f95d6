#include "fw/model/head_back.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "fw/model/head_shell.hpp"
#include "fw/model/srgb.hpp"

namespace fw::model {
namespace {

constexpr float kFullTurn = 2.0f * std::numbers::pi_v<float>;

float smooth_ramp(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The mean colour around the point where ray k's hidden part takes its
// colour: a few texels along the ray and to either side of it, those the
// alpha shows. Nothing shown (a ray off the texture): nullopt.
std::optional<glm::vec3> ray_colour(const RgbaImage& texture, const TextureFrame& frame, glm::vec2 centre, float phi,
                                    float radius, float ray_step) {
  glm::vec3 sum(0.0f);
  int count = 0;
  for (const float along : {-0.1f, -0.05f, 0.0f, 0.05f, 0.1f})
    for (const float across : {-0.5f, -0.25f, 0.0f, 0.25f, 0.5f}) {
      const float angle = phi + across * ray_step;
      const glm::vec2 uv = frame.to_uv(centre + (radius + along) * glm::vec2(std::cos(angle), std::sin(angle)));
      const int x = static_cast<int>(std::floor(uv.x * static_cast<float>(texture.width)));
      const int y = static_cast<int>(std::floor((1.0f - uv.y) * static_cast<float>(texture.height)));
      if (x < 0 || y < 0 || x >= texture.width || y >= texture.height) continue;
      const std::uint8_t* px = texture.at(x, y);
      if (px[3] < 128) continue;
      sum += glm::vec3(linear_from_srgb(px[0]), linear_from_srgb(px[1]), linear_from_srgb(px[2]));
      ++count;
    }
  if (count == 0) return std::nullopt;
  return sum / static_cast<float>(count);
}

// Each ray's colour, smoothed around the head over about 70 degrees with a
// triangle (which cancels a pattern that alternates from ray to ray): a
// strand of hair or a frame of glasses on one ray is not the side of a head.
std::vector<glm::vec3> smoothed_ray_colours(const RgbaImage& texture, const TextureFrame& frame, glm::vec2 centre,
                                            std::span<const float> colour_radius) {
  const std::size_t n = colour_radius.size();
  const float step = kFullTurn / static_cast<float>(n);
  std::vector<std::optional<glm::vec3>> raw(n);
  for (std::size_t k = 0; k < n; ++k)
    raw[k] = ray_colour(texture, frame, centre, outline_ray_angle(k, n), colour_radius[k], step);
  constexpr int kReach = 3;
  constexpr float kWeights[] = {1.0f, 2.0f, 3.0f, 4.0f, 3.0f, 2.0f, 1.0f};
  glm::vec3 fallback(0.0f);  // a ray with nothing shown near it: the mean of all
  int shown = 0;
  for (const auto& c : raw)
    if (c) fallback += *c, ++shown;
  fallback = shown ? fallback / static_cast<float>(shown) : glm::vec3(0.5f);
  std::vector<glm::vec3> smoothed(n);
  for (std::size_t k = 0; k < n; ++k) {
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (int d = -kReach; d <= kReach; ++d) {
      const auto& c = raw[(k + n + static_cast<std::size_t>(d + static_cast<int>(n))) % n];
      if (!c) continue;
      sum += kWeights[d + kReach] * *c;
      weight += kWeights[d + kReach];
    }
    smoothed[k] = weight > 0 ? sum / weight : fallback;
  }
  return smoothed;
}

}  // namespace

glm::vec2 head_back_uv(float phi, float t) {
  return kHeadBackPatch.centre + kHeadBackPatch.radius * std::clamp(t, 0.0f, 1.0f) *
                                     glm::vec2(std::cos(phi), std::sin(phi));
}

bool on_head_back_patch(glm::vec2 uv) {
  return glm::length(uv - kHeadBackPatch.centre) <= kHeadBackPatch.radius * 1.001f;
}

void paint_head_back(RgbaImage& texture, const TextureFrame& frame, glm::vec2 shell_centre,
                     std::span<const float> colour_radius) {
  assert(!colour_radius.empty());
  const std::vector<glm::vec3> rays = smoothed_ray_colours(texture, frame, shell_centre, colour_radius);
  const std::size_t n = rays.size();
  // The top of the head's colour (hair, a cap, a bald crown) is the back's.
  glm::vec3 top(0.0f);
  float top_weight = 0.0f;
  for (std::size_t k = 0; k < n; ++k) {
    const float w = std::max(0.0f, std::sin(outline_ray_angle(k, n)) - 0.3f);
    top += w * rays[k];
    top_weight += w;
  }
  top /= top_weight;
  // The disc and a margin of a quarter of its radius, clamped to the rim.
  const float reach = kHeadBackPatch.radius * 1.25f;
  const auto pixel_range = [&](float low, float high, int size) {
    return std::pair{std::max(0, static_cast<int>(std::floor(low * static_cast<float>(size)))),
                     std::min(size - 1, static_cast<int>(std::ceil(high * static_cast<float>(size))))};
  };
  const glm::vec2 c = kHeadBackPatch.centre;
  const auto [x0, x1] = pixel_range(c.x - reach, c.x + reach, texture.width);
  const auto [y0, y1] = pixel_range(1.0f - (c.y + reach), 1.0f - (c.y - reach), texture.height);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(texture.width),
                         1.0f - (static_cast<float>(y) + 0.5f) / static_cast<float>(texture.height));
      const glm::vec2 d = (uv - c) / kHeadBackPatch.radius;
      const float t = std::min(1.0f, glm::length(d));
      const float phi = std::atan2(d.y, d.x);
      const glm::vec3 edge = between_rays(std::span<const glm::vec3>(rays), phi);
      // Going back, the sides and the crown become the top's colour; the
      // neck's rays keep the neck's but for the back of the skull above
      // the nape, so that every direction meets in one colour at the pole.
      // The silhouette's own colour reaches back only over the band that
      // holds the ears (t above about 0.75; in profile the ear sits just
      // behind the head's widest section): behind them, on every ray above
      // the ear lobes, a head is its hair, or its crown's skin if bald.
      // Reaching back half the way, the skin of the cheeks at the sides of
      // the photo covered the sides of the head, and a head turned 60
      // degrees read as bald behind its hairline.
      const float crown = std::max(smooth_ramp(-0.65f, -0.25f, std::sin(phi)), 1.0f - smooth_ramp(0.3f, 0.6f, t));
      const glm::vec3 back = glm::mix(edge, top, crown);
      const glm::vec3 colour = glm::mix(back, edge, smooth_ramp(0.7f, 0.95f, t));
      std::uint8_t* px = texture.at(x, y);
      px[0] = srgb_from_linear(colour.r);
      px[1] = srgb_from_linear(colour.g);
      px[2] = srgb_from_linear(colour.b);
      px[3] = 255;
    }
}

std::vector<glm::vec3> photo_light_normals(const Mesh& shell, std::vector<glm::vec3> normals) {
  for (std::size_t v = 0; v < shell.uvs.size() && v < normals.size(); ++v)
    if (on_head_back_patch(shell.uvs[v])) normals[v] = glm::vec3(0.0f, 0.0f, 1.0f);
  return normals;
}

}  // namespace fw::model
