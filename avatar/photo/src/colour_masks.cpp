#include "colour_masks.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "face_alignment.hpp"

namespace fw::photo {
namespace {

// Corners (u,v) = (0,0), (1,0), (1,1), (0,1) of each region on the generic
// face; the inner control points are spread evenly between them, so the
// patch starts as a plane quad and takes the face's shape through the fit.
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
  return {m(q.p10), m(q.p00), m(q.p01), m(q.p11)};  // keep the orientation
}

float bernstein(int i, float t) {
  static constexpr float kBinomial[4] = {1, 3, 3, 1};
  return kBinomial[i] * std::pow(t, static_cast<float>(i)) * std::pow(1 - t, static_cast<float>(3 - i));
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
  glm::vec2 p(0.0f);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      p += bernstein(i, u) * bernstein(j, v) * patch[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
  return p;
}

float evaluate_shade(float u, float v) {
  // With a = (0,1,1,0), sum_i a_i B_i(t) = 3t(1-t); its peak 3/4 at t = 1/2.
  const auto profile = [](float t) { return (bernstein(1, t) + bernstein(2, t)) / 0.75f; };
  return profile(u) * profile(v);
}

std::array<cv::Mat, kMaskRegionCount> render_region_masks(const ThinPlateSpline& warp,
                                                          const model::TextureFrame& frame, int size) {
  constexpr int kSteps = 40;  // parametric quads per side: finer than the mask's pixels
  std::array<cv::Mat, kMaskRegionCount> masks;
  for (std::size_t r = 0; r < kMaskRegionCount; ++r) {
    cv::Mat mask = cv::Mat::zeros(size, size, CV_32F);
    for (BezierPatch patch : region_patches(static_cast<MaskRegion>(r))) {
      for (auto& row : patch)
        for (glm::vec2& p : row) p = warp(p);  // the template's patch, on this face
      for (int i = 0; i < kSteps; ++i)
        for (int j = 0; j < kSteps; ++j) {
          const float u0 = static_cast<float>(i) / kSteps, u1 = static_cast<float>(i + 1) / kSteps;
          const float v0 = static_cast<float>(j) / kSteps, v1 = static_cast<float>(j + 1) / kSteps;
          std::vector<cv::Point> quad;
          for (const auto& [u, v] : {std::pair{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}) {
            const cv::Point2f px = model_to_texture_px(evaluate_patch(patch, u, v), frame, size);
            quad.emplace_back(cvRound(px.x), cvRound(px.y));
          }
          const float shade = evaluate_shade(0.5f * (u0 + u1), 0.5f * (v0 + v1));
          const cv::Rect box = cv::boundingRect(quad) & cv::Rect(0, 0, size, size);
          if (box.empty()) continue;
          cv::Mat quad_mask = cv::Mat::zeros(box.size(), CV_8U);
          for (cv::Point& corner : quad) corner -= box.tl();
          cv::fillConvexPoly(quad_mask, quad, cv::Scalar(1));
          cv::Mat target = mask(box);
          target.setTo(cv::Scalar(shade), quad_mask & (target < shade));
        }
    }
    // Quads meet edge to edge; a slight blur hides their steps.
    cv::GaussianBlur(mask, mask, cv::Size(3, 3), 0.8);
    mask.convertTo(masks[r], CV_8U, 255.0);
  }
  return masks;
}

std::array<std::uint8_t, 3> estimate_skin_tone(const cv::Mat& texture, const std::array<cv::Mat, kMaskRegionCount>& masks) {
  cv::Mat small;
  cv::resize(texture, small, masks[0].size(), 0, 0, cv::INTER_AREA);
  std::array<std::vector<std::uint8_t>, 3> channels;
  for (int y = 0; y < small.rows; ++y)
    for (int x = 0; x < small.cols; ++x) {
      const bool skin = masks[static_cast<std::size_t>(MaskRegion::forehead)].at<std::uint8_t>(y, x) > 128 ||
                        masks[static_cast<std::size_t>(MaskRegion::cheek_left)].at<std::uint8_t>(y, x) > 128 ||
                        masks[static_cast<std::size_t>(MaskRegion::cheek_right)].at<std::uint8_t>(y, x) > 128;
      if (!skin) continue;
      const cv::Vec3b c = small.at<cv::Vec3b>(y, x);
      for (int k = 0; k < 3; ++k) channels[static_cast<std::size_t>(k)].push_back(c[k]);
    }
  std::array<std::uint8_t, 3> rgb{128, 128, 128};
  for (int k = 0; k < 3; ++k) {
    auto& v = channels[static_cast<std::size_t>(k)];
    if (v.empty()) return rgb;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    rgb[static_cast<std::size_t>(2 - k)] = v[v.size() / 2];
  }
  return rgb;
}

}  // namespace fw::photo
