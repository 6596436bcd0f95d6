// The neck's shadow under a steep jaw: its upper edge runs along the jaw
// line, not in steps of whole texels (the staircase a turned head showed
// along its jaw, below the ear).
#include "neck_shadow.hpp"

#include <cmath>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include "face_alignment.hpp"

namespace fw::photo {
namespace {

// The product's texture: 320 texels over 5.4 units.
constexpr int kTexels = 320;
const model::TextureFrame kTextureFrame{{-2.7f, -2.7f}, 5.4f};
constexpr float kJawSlope = 3.0f;  // as steep as a jaw below the ear
constexpr std::uint8_t kNeckGrey = 200;

// The jaw's lower part (landmarks 3..13) a V: straight lines of slope 3
// down to the chin at (0, -1.5).
ModelLandmarks steep_jaw() {
  ModelLandmarks l{};
  for (int i = 3; i <= 13; ++i) {
    const float x = -0.5f + 0.1f * static_cast<float>(i - 3);
    l[static_cast<std::size_t>(i)] = {x, -1.5f + kJawSlope * std::abs(x)};
  }
  return l;
}

// Where along a row the shadow's edge lies (texels, between texel
// centres): where the shading, from the shadow on the left to the lit jaw on
// the right, crosses the middle of its range.
float edge_along_row(const cv::Mat& bgra, int row, int from, int to) {
  constexpr float kMiddle = 0.78f;  // between 0.55 under the jaw and 1
  for (int col = from; col < to; ++col) {
    const float a = bgra.at<cv::Vec4b>(row, col)[0] / float(kNeckGrey);
    const float b = bgra.at<cv::Vec4b>(row, col + 1)[0] / float(kNeckGrey);
    if (a < kMiddle && b >= kMiddle) return static_cast<float>(col) + (kMiddle - a) / (b - a);
  }
  return -1.0f;
}

TEST(NeckShadow, ItsEdgeRunsAlongASteepJawWithoutSteps) {
  cv::Mat bgra(kTexels, kTexels, CV_8UC4, cv::Scalar(kNeckGrey, kNeckGrey, kNeckGrey, 255));
  const cv::Mat matte(kTexels, kTexels, CV_8U, cv::Scalar(0));  // nothing the person's own: all may be shaded
  shade_neck(bgra, matte, steep_jaw(), kTextureFrame);
  // The left branch, away from its ends: from x = -0.4 to -0.1.
  const int top = static_cast<int>(model_to_texture_px({0.0f, -1.5f + kJawSlope * 0.4f}, kTextureFrame, kTexels).y);
  const int bottom = static_cast<int>(model_to_texture_px({0.0f, -1.5f + kJawSlope * 0.1f}, kTextureFrame, kTexels).y);
  const int from = static_cast<int>(model_to_texture_px({-0.6f, 0.0f}, kTextureFrame, kTexels).x);
  const int to = static_cast<int>(model_to_texture_px({0.0f, 0.0f}, kTextureFrame, kTexels).x);
  std::vector<float> rows, edges;
  for (int row = top; row <= bottom; ++row) {
    const float edge = edge_along_row(bgra, row, from, to);
    ASSERT_GE(edge, 0.0f) << "row " << row << " crosses no shadow edge";
    rows.push_back(static_cast<float>(row));
    edges.push_back(edge);
  }
  // A straight jaw: the edge a straight line across the rows, a third of a
  // texel further right on each. Measured down each column, the edge stood
  // still for three rows and then jumped a texel.
  const float n = static_cast<float>(rows.size());
  float mean_row = 0, mean_edge = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) mean_row += rows[i] / n, mean_edge += edges[i] / n;
  float covariance = 0, variance = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    covariance += (rows[i] - mean_row) * (edges[i] - mean_edge);
    variance += (rows[i] - mean_row) * (rows[i] - mean_row);
  }
  const float per_row = covariance / variance;
  EXPECT_NEAR(per_row, 1.0f / kJawSlope, 0.02f);
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_NEAR(edges[i], mean_edge + per_row * (rows[i] - mean_row), 0.1f) << "row " << rows[i];
}

// Down a column: the first row where the shading falls below the middle
// of its range (from the lit face above into the shadow), or -1.
int edge_down_column(const cv::Mat& bgra, int col) {
  for (int row = 0; row < bgra.rows; ++row)
    if (bgra.at<cv::Vec4b>(row, col)[0] / float(kNeckGrey) < 0.78f) return row;
  return -1;
}

// Beside the jaw's lower part the edge climbs toward the ear, as the jaw's
// ramus does. Kept at the jaw end's height, it ran straight back across the
// side of a turned head, a ledge under the cheek.
TEST(NeckShadow, BesideTheJawItsEdgeRisesTowardTheEar) {
  cv::Mat bgra(kTexels, kTexels, CV_8UC4, cv::Scalar(kNeckGrey, kNeckGrey, kNeckGrey, 255));
  const cv::Mat matte(kTexels, kTexels, CV_8U, cv::Scalar(0));
  const ModelLandmarks jaw = steep_jaw();
  shade_neck(bgra, matte, jaw, kTextureFrame);
  const float end_x = jaw[3].x;  // the jaw's lower part ends at x = -0.5
  const auto column = [&](float beside) {
    return static_cast<int>(model_to_texture_px({end_x - beside, 0.0f}, kTextureFrame, kTexels).x);
  };
  const int near = edge_down_column(bgra, column(0.05f)), far = edge_down_column(bgra, column(0.1f));
  ASSERT_GE(near, 0);
  ASSERT_GE(far, 0);
  // 0.05 units further out, 0.15 units higher: about 9 texels.
  EXPECT_GT(near - far, 5) << "the edge stays level beside the jaw";
}

}  // namespace
}  // namespace fw::photo
