#include "fw/model/vascular_masks.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace fw::model {
namespace {

// Corners (u,v) = (0,0), (1,0), (1,1), (0,1) of each region on the generic
// face; inner control points are spread evenly between them, so the patch
// starts as a plane quad and takes a face's shape through the warp.
struct Quad {
  glm::vec2 p00, p10, p11, p01;
};

BezierPatch patch_from_quad(const Quad& q) {
  BezierPatch patch{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const float u = static_cast<float>(i) / 3.0f, v = static_cast<float>(j) / 3.0f;
      patch[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          (1 - u) * (1 - v) * q.p00 + u * (1 - v) * q.p10 + u * v * q.p11 + (1 - u) * v * q.p01;
    }
  return patch;
}

Quad mirrored(const Quad& q) {
  const auto m = [](glm::vec2 p) { return glm::vec2(-p.x, p.y); };
  return {m(q.p10), m(q.p00), m(q.p01), m(q.p11)};  // keeps the orientation
}

float bernstein(int i, float t) {
  static constexpr float kBinomial[4] = {1, 3, 3, 1};
  return kBinomial[i] * std::pow(t, static_cast<float>(i)) * std::pow(1 - t, static_cast<float>(3 - i));
}

// The four cubic Bernstein weights at t. The masks are drawn from 161 x 161
// samples a patch: computing the weights once per parameter value instead of
// once per sample (each a pair of powf calls) took a process that draws
// them (every server start, and every client that shows a procedural face)
// from 1.2 s of CPU to 0.6 s.
using Basis = std::array<float, 4>;

Basis bernstein_basis(float t) { return {bernstein(0, t), bernstein(1, t), bernstein(2, t), bernstein(3, t)}; }

glm::vec2 patch_point(const BezierPatch& patch, const Basis& bu, const Basis& bv) {
  glm::vec2 p(0.0f);
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) p += bu[i] * bv[j] * patch[i][j];
  return p;
}

// With a = (0,1,1,0), sum_i a_i B_i(t) = 3t(1-t), which peaks at 3/4.
float shade_profile(const Basis& b) { return (b[1] + b[2]) / 0.75f; }

// Blurs a mask with a 3x3 binomial kernel: samples land on a grid finer
// than the mask, but a pixel can still miss every sample at a patch's edge.
void soften(std::vector<float>& mask, int size) {
  std::vector<float> out(mask.size(), 0.0f);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      float sum = 0, weight = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int sx = x + dx, sy = y + dy;
          if (sx < 0 || sy < 0 || sx >= size || sy >= size) continue;
          const float w = static_cast<float>((2 - std::abs(dx)) * (2 - std::abs(dy)));
          sum += w * mask[static_cast<std::size_t>(sy * size + sx)];
          weight += w;
        }
      out[static_cast<std::size_t>(y * size + x)] = sum / weight;
    }
  mask.swap(out);
}

}  // namespace

std::vector<BezierPatch> region_patches(MaskRegion region) {
  // On the person's right (viewer's left, x < 0); the left ones mirror these.
  const Quad cheek_right{{-1.05f, -1.0f}, {-0.3f, -0.85f}, {-0.28f, -0.15f}, {-1.0f, -0.1f}};
  const Quad side_right{{-1.42f, -1.1f}, {-1.0f, -1.1f}, {-1.02f, 0.45f}, {-1.42f, 0.45f}};
  switch (region) {
    case MaskRegion::forehead: return {patch_from_quad({{-0.85f, 0.42f}, {0.85f, 0.42f}, {0.75f, 1.25f}, {-0.75f, 1.25f}})};
    case MaskRegion::cheek_right: return {patch_from_quad(cheek_right)};
    case MaskRegion::cheek_left: return {patch_from_quad(mirrored(cheek_right))};
    case MaskRegion::nose: return {patch_from_quad({{-0.3f, -0.82f}, {0.3f, -0.82f}, {0.13f, 0.08f}, {-0.13f, 0.08f}})};
    case MaskRegion::sides: return {patch_from_quad(side_right), patch_from_quad(mirrored(side_right))};
    case MaskRegion::face: return {patch_from_quad({{-1.25f, -2.05f}, {1.25f, -2.05f}, {1.25f, 1.45f}, {-1.25f, 1.45f}})};
    case MaskRegion::count: break;
  }
  return {};
}

glm::vec2 evaluate_patch(const BezierPatch& patch, float u, float v) {
  return patch_point(patch, bernstein_basis(u), bernstein_basis(v));
}

float evaluate_shade(float u, float v) { return shade_profile(bernstein_basis(u)) * shade_profile(bernstein_basis(v)); }

std::array<Mask, kMaskRegionCount> render_region_masks(const std::function<glm::vec2(glm::vec2)>& warp,
                                                       const TextureFrame& frame, int size) {
  // Parametric samples per patch side: several per mask pixel even for the
  // largest patch (the whole face spans about 40 of 64 pixels).
  constexpr int kSteps = 160;
  std::array<Basis, kSteps + 1> basis;
  std::array<float, kSteps + 1> profile;
  for (int i = 0; i <= kSteps; ++i) {
    basis[static_cast<std::size_t>(i)] = bernstein_basis(static_cast<float>(i) / kSteps);
    profile[static_cast<std::size_t>(i)] = shade_profile(basis[static_cast<std::size_t>(i)]);
  }
  std::array<Mask, kMaskRegionCount> masks;
  for (std::size_t r = 0; r < kMaskRegionCount; ++r) {
    std::vector<float> mask(static_cast<std::size_t>(size * size), 0.0f);
    for (BezierPatch patch : region_patches(static_cast<MaskRegion>(r))) {
      for (auto& row : patch)
        for (glm::vec2& p : row) p = warp(p);
      for (std::size_t i = 0; i <= kSteps; ++i)
        for (std::size_t j = 0; j <= kSteps; ++j) {
          const glm::vec2 uv = frame.to_uv(patch_point(patch, basis[i], basis[j]));
          const int x = static_cast<int>(uv.x * static_cast<float>(size));
          const int y = static_cast<int>((1.0f - uv.y) * static_cast<float>(size));
          if (x < 0 || y < 0 || x >= size || y >= size) continue;
          float& m = mask[static_cast<std::size_t>(y * size + x)];
          m = std::max(m, profile[i] * profile[j]);
        }
    }
    soften(mask, size);
    masks[r].resize(mask.size());
    std::transform(mask.begin(), mask.end(), masks[r].begin(),
                   [](float m) { return static_cast<std::uint8_t>(std::lround(std::clamp(m, 0.0f, 1.0f) * 255.0f)); });
  }
  return masks;
}

std::array<RgbaImage, 2> pack_region_masks(const std::array<Mask, kMaskRegionCount>& masks, int size) {
  std::array<RgbaImage, 2> images{RgbaImage(size, size), RgbaImage(size, size)};
  for (std::size_t i = 0; i < static_cast<std::size_t>(size * size); ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      images[0].pixels[i * 4 + k] = masks[k][i];
      images[1].pixels[i * 4 + k] = masks[3 + k][i];
      images[0].pixels[i * 4 + 3] = images[1].pixels[i * 4 + 3] = 255;
    }
  return images;
}

}  // namespace fw::model
