#include "photo_expression.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>

#include "face_alignment.hpp"
#include "thin_plate_spline.hpp"

namespace fw::photo {
namespace {

namespace lm = model::landmarks;

// The action units a casual photo shows, which its landmarks can tell:
// inner and outer brow raiser, brow lowerer, cheek raiser, lip corner
// puller (the smile), lip corner depressor, lips part, jaw drop.
constexpr std::array<int, 7> kEstimatedUnits = {1, 2, 4, 6, 12, 25, 26};
// How strongly each unit is pulled toward 0 (squared model units): brows
// sit high or low by nature, so their raisers need more evidence than a
// mouth whose corners turn up.
float pull_toward_neutral(int au) { return au <= 4 ? 0.004f : 0.0008f; }

// A broad grin is more than the generic face's lip-corner pull at its FACS
// maximum: what is taken out may go past 1.
constexpr double kMostToUndo = 2.5;

// Landmarks that tell an expression: brows, eyes, mouth. The jaw line and
// the nose are the person's own shape.
bool in(std::size_t i, int begin, int end) { return static_cast<int>(i) >= begin && static_cast<int>(i) < end; }
bool on_mouth(std::size_t i) { return in(i, lm::kOuterLipBegin, lm::kInnerLipEnd); }
bool on_right_brow(std::size_t i) { return in(i, lm::kBrowRightBegin, lm::kBrowRightEnd); }
bool on_left_brow(std::size_t i) { return in(i, lm::kBrowLeftBegin, lm::kBrowLeftEnd); }
bool tells_expression(std::size_t i) {
  return on_right_brow(i) || on_left_brow(i) || in(i, lm::kEyeRightBegin, lm::kEyeLeftEnd) || on_mouth(i);
}

// Least squares with box bounds by coordinate descent: small (a few dozen
// unknowns), convex, and exact in each coordinate.
std::vector<double> solve_bounded(const std::vector<std::vector<double>>& columns, const std::vector<double>& target,
                                  const std::vector<double>& ridge, const std::vector<double>& lower,
                                  const std::vector<double>& upper) {
  const std::size_t n = columns.size(), rows = target.size();
  std::vector<double> x(n, 0.0), residual = target, norms(n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t r = 0; r < rows; ++r) norms[k] += columns[k][r] * columns[k][r];
  for (int sweep = 0; sweep < 300; ++sweep) {
    double change = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (norms[k] + ridge[k] <= 0) continue;
      double dot = 0;
      for (std::size_t r = 0; r < rows; ++r) dot += columns[k][r] * residual[r];
      const double best = std::clamp((dot + norms[k] * x[k]) / (norms[k] + ridge[k]), lower[k], upper[k]);
      const double step = best - x[k];
      if (step == 0) continue;
      for (std::size_t r = 0; r < rows; ++r) residual[r] -= step * columns[k][r];
      x[k] = best;
      change = std::max(change, std::abs(step));
    }
    if (change < 1e-7) break;
  }
  return x;
}

// What the action units leave of a grin (teeth between parted lips, corners
// above the lips' middle) is closed and levelled as a neutral mouth is: the
// inner lips meet, each outer lip follows its inner lip (the person's lip
// thickness stays), and the corners sit as high above the lips' middle as
// the generic face's do.
void close_mouth(ModelLandmarks& mouth) {
  const auto& neutral_face = model::landmark_template();
  const auto at = [&](int i) -> glm::vec2& { return mouth[static_cast<std::size_t>(i)]; };
  // Inner lip pairs, upper then lower, left to right, with the outer lip
  // points that follow each.
  struct Pair {
    int upper, lower;
    std::array<int, 2> outer_upper, outer_lower;
  };
  constexpr std::array<Pair, 3> kPairs = {Pair{61, 67, {49, 50}, {59, 58}}, Pair{62, 66, {51, 51}, {57, 57}},
                                          Pair{63, 65, {52, 53}, {56, 55}}};
  // The landmarks keep the generic face's slit between closed lips: the
  // texture's spline needs distinct points (lips squeezed onto one line
  // would fold the picture between them). The mesh shuts it
  // (landmarks_for_fit), so that nothing of the mouth's inside shows at rest.
  const float slit = neutral_face[62].y - neutral_face[66].y;
  float middle = 0;
  for (const Pair& pair : kPairs) {
    const float meet = 0.5f * (at(pair.upper).y + at(pair.lower).y);
    const float up = meet + 0.5f * slit - at(pair.upper).y, down = meet - 0.5f * slit - at(pair.lower).y;
    at(pair.upper).y += up;
    at(pair.lower).y += down;
    // Each outer point follows once, even where two pairs share it.
    for (std::size_t k = 0; k < 2; ++k) {
      if (k == 0 || pair.outer_upper[1] != pair.outer_upper[0]) at(pair.outer_upper[k]).y += up;
      if (k == 0 || pair.outer_lower[1] != pair.outer_lower[0]) at(pair.outer_lower[k]).y += down;
    }
    if (pair.upper == 62) middle = meet;
  }
  const float template_middle = 0.5f * (neutral_face[62].y + neutral_face[66].y);
  for (const int corner : {lm::kMouthCornerRight, lm::kMouthCornerLeft}) {
    const int inner = corner == lm::kMouthCornerRight ? 60 : 64;
    const float rise = middle + (neutral_face[static_cast<std::size_t>(corner)].y - template_middle) - at(corner).y;
    at(corner).y += rise;
    at(inner).y += rise;
    // The lip points next to the corner follow halfway, so the lips' curve
    // stays smooth.
    const std::array<int, 2> next = corner == lm::kMouthCornerRight ? std::array<int, 2>{49, 59}
                                                                    : std::array<int, 2>{53, 55};
    for (const int n : next) at(n).y += 0.5f * rise;
  }
}

// An expression moves the lids, not the eyes: each eye's landmarks keep
// their centre, which the model frame is built on.
void keep_eye_centres(const ModelLandmarks& photo, ModelLandmarks& neutral) {
  for (const auto& [begin, end] : {std::pair{lm::kEyeRightBegin, lm::kEyeRightEnd},
                                  std::pair{lm::kEyeLeftBegin, lm::kEyeLeftEnd}}) {
    glm::vec2 drift(0.0f);
    for (int i = begin; i < end; ++i)
      drift += (neutral[static_cast<std::size_t>(i)] - photo[static_cast<std::size_t>(i)]) / float(end - begin);
    for (int i = begin; i < end; ++i) neutral[static_cast<std::size_t>(i)] -= drift;
  }
}

}  // namespace

glm::vec2 picture_motion(const model::GenericFace& generic, const model::Morph& morph, std::size_t i) {
  const std::uint32_t v = generic.landmark_vertices[i];
  return glm::vec2(morph.vertex_delta[v]) - morph.uv_delta[v] * generic.texture_frame.size;
}

PhotoExpression estimate_expression(const model::GenericFace& generic, const ModelLandmarks& landmarks) {
  const auto& neutral_face = model::landmark_template();
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < landmarks.size(); ++i)
    if (tells_expression(i)) used.push_back(i);
  const std::size_t rows = used.size() * 2;

  std::vector<double> target(rows);
  for (std::size_t r = 0; r < used.size(); ++r) {
    const glm::vec2 d = landmarks[used[r]] - neutral_face[used[r]];
    target[2 * r] = d.x, target[2 * r + 1] = d.y;
  }

  std::vector<std::vector<double>> columns;
  std::vector<double> ridge, lower, upper;
  std::vector<int> channel_of_column;
  for (std::size_t c = 0; c < codec::kAuChannelCount; ++c) {
    const int au = codec::kAuChannels[c].au;
    if (std::find(kEstimatedUnits.begin(), kEstimatedUnits.end(), au) == kEstimatedUnits.end()) continue;
    std::vector<double> column(rows);
    for (std::size_t r = 0; r < used.size(); ++r) {
      const glm::vec2 m = picture_motion(generic, generic.action_units[c], used[r]);
      column[2 * r] = m.x, column[2 * r + 1] = m.y;
    }
    columns.push_back(std::move(column));
    ridge.push_back(pull_toward_neutral(au));
    lower.push_back(0.0), upper.push_back(kMostToUndo);
    channel_of_column.push_back(static_cast<int>(c));
  }
  // The person's own shape: where the mouth sits and how wide it is, how
  // high each brow is. Free, and never taken out.
  glm::vec2 mouth_centre(0.0f);
  for (int i = lm::kOuterLipBegin; i < lm::kInnerLipEnd; ++i)
    mouth_centre += neutral_face[static_cast<std::size_t>(i)] / float(lm::kInnerLipEnd - lm::kOuterLipBegin);
  const auto shape_column = [&](auto value) {
    std::vector<double> column(rows);
    for (std::size_t r = 0; r < used.size(); ++r) {
      const glm::vec2 v = value(used[r]);
      column[2 * r] = v.x, column[2 * r + 1] = v.y;
    }
    columns.push_back(std::move(column));
    ridge.push_back(0.0), lower.push_back(-1e9), upper.push_back(1e9);
  };
  shape_column([&](std::size_t i) { return on_mouth(i) ? glm::vec2(1, 0) : glm::vec2(0); });
  shape_column([&](std::size_t i) { return on_mouth(i) ? glm::vec2(0, 1) : glm::vec2(0); });
  shape_column([&](std::size_t i) {
    return on_mouth(i) ? glm::vec2(neutral_face[i].x - mouth_centre.x, 0) : glm::vec2(0);
  });
  shape_column([&](std::size_t i) { return on_right_brow(i) ? glm::vec2(0, 1) : glm::vec2(0); });
  shape_column([&](std::size_t i) { return on_left_brow(i) ? glm::vec2(0, 1) : glm::vec2(0); });

  const std::vector<double> x = solve_bounded(columns, target, ridge, lower, upper);
  PhotoExpression expression;
  expression.neutral = landmarks;
  for (std::size_t k = 0; k < channel_of_column.size(); ++k) {
    const auto c = static_cast<std::size_t>(channel_of_column[k]);
    expression.au[c] = static_cast<float>(x[k]);
    if (x[k] <= 0) continue;
    for (std::size_t i = 0; i < landmarks.size(); ++i)
      expression.neutral[i] -= static_cast<float>(x[k]) * picture_motion(generic, generic.action_units[c], i);
  }
  close_mouth(expression.neutral);
  keep_eye_centres(landmarks, expression.neutral);
  for (std::size_t i = 0; i < landmarks.size(); ++i)
    expression.largest_move = std::max(expression.largest_move, glm::length(landmarks[i] - expression.neutral[i]));
  return expression;
}

cv::Mat neutralise_texture(const cv::Mat& texture, const model::TextureFrame& frame, const ModelLandmarks& photo,
                           const ModelLandmarks& neutral) {
  std::vector<glm::vec2> from(neutral.begin(), neutral.end()), to(photo.begin(), photo.end());
  // The texture's border stays where it is: the expression moves the face,
  // not the hair and background around it.
  constexpr int kBorderPoints = 8;
  for (int i = 0; i < kBorderPoints; ++i)
    for (const glm::vec2 uv : {glm::vec2(i / float(kBorderPoints), 0.0f), glm::vec2(1.0f, i / float(kBorderPoints)),
                               glm::vec2(1.0f - i / float(kBorderPoints), 1.0f),
                               glm::vec2(0.0f, 1.0f - i / float(kBorderPoints))}) {
      from.push_back(frame.to_model(uv));
      to.push_back(frame.to_model(uv));
    }
  ThinPlateSpline neutral_to_photo;
  // A little smoothing: dlib's lip points are not exact, and a spline
  // through each of them would ripple where the lips are squeezed together.
  if (!neutral_to_photo.fit(from, to, 2e-4f)) return texture.clone();
  // The spline is smooth: evaluated on a coarse grid and interpolated.
  constexpr int kStep = 4;
  const int size = texture.cols, coarse = size / kStep + 1;
  cv::Mat coarse_x(coarse, coarse, CV_32F), coarse_y(coarse, coarse, CV_32F);
  for (int row = 0; row < coarse; ++row)
    for (int col = 0; col < coarse; ++col) {
      const cv::Point2f px(static_cast<float>(col * kStep), static_cast<float>(row * kStep));
      const cv::Point2f source = model_to_texture_px(neutral_to_photo(texture_px_to_model(px, frame, size)), frame, size);
      coarse_x.at<float>(row, col) = source.x;
      coarse_y.at<float>(row, col) = source.y;
    }
  cv::Mat map_x, map_y, neutral_texture;
  const cv::Size span((coarse - 1) * kStep + 1, (coarse - 1) * kStep + 1);
  cv::resize(coarse_x, map_x, span, 0, 0, cv::INTER_LINEAR);
  cv::resize(coarse_y, map_y, span, 0, 0, cv::INTER_LINEAR);
  const cv::Rect whole(0, 0, size, size);
  cv::remap(texture, neutral_texture, map_x(whole), map_y(whole), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return neutral_texture;
}

}  // namespace fw::photo
