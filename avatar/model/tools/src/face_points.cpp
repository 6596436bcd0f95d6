#include "face_points.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "fw/model/landmark_template.hpp"

namespace fw::facegen {
namespace {

namespace lm = model::landmarks;

glm::vec2 mean_of(int begin, int end) {
  glm::vec2 sum(0.0f);
  for (int i = begin; i < end; ++i) sum += model::landmark_template()[static_cast<std::size_t>(i)];
  return sum / static_cast<float>(end - begin);
}

// Rings around an eye: each contour point pushed away from the eye centre,
// upper and lower points also moved vertically, so the lids get rows of
// vertices that can slide without the eye contour itself distorting.
void add_eye_rings(int begin, int end, std::vector<glm::vec2>& points) {
  const glm::vec2 centre = mean_of(begin, end);
  for (int ring = 1; ring <= 2; ++ring) {
    for (int i = begin; i < end; ++i) {
      const glm::vec2 p = model::landmark_template()[static_cast<std::size_t>(i)];
      const glm::vec2 d = p - centre;
      const bool corner = (i == begin || i == begin + 3);
      const float vertical = corner ? 0.0f : (d.y > 0 ? 0.065f : -0.07f) * static_cast<float>(ring);
      points.push_back(centre + d * (1.0f + 0.3f * static_cast<float>(ring)) + glm::vec2(0.0f, vertical));
    }
  }
}

// The hairline: an elliptic arc from temple to temple over the forehead.
std::vector<glm::vec2> hairline_arc() {
  std::vector<glm::vec2> arc;
  constexpr int kSteps = 10;
  for (int k = 0; k <= kSteps; ++k) {
    const float t = std::numbers::pi_v<float> * static_cast<float>(k) / kSteps;
    arc.emplace_back(1.12f * std::cos(t), 0.32f + 1.03f * std::sin(t));
  }
  return arc;
}

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 ab = b - a;
  const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab));
}

float distance_to_polygon_edge(glm::vec2 p, const std::vector<glm::vec2>& polygon) {
  float best = 1e9f;
  for (std::size_t i = 0; i < polygon.size(); ++i)
    best = std::min(best, distance_to_segment(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  return best;
}

float distance_to_points(glm::vec2 p, const std::vector<glm::vec2>& points) {
  float best = 1e9f;
  for (const glm::vec2& q : points) best = std::min(best, glm::length(p - q));
  return best;
}

// A hexagonal grid of candidates, taken in mirrored pairs so the point set
// stays exactly left/right symmetric, wherever the face is not yet covered.
void add_fill(const std::vector<glm::vec2>& outline, std::vector<glm::vec2>& points) {
  constexpr float kSpacing = 0.2f;
  constexpr float kMinDistance = 0.135f;
  constexpr float kOutlineMargin = 0.1f;
  const float row_height = kSpacing * std::sqrt(3.0f) / 2.0f;
  for (int row = 0; row < 24; ++row) {
    const float y = -1.8f + static_cast<float>(row) * row_height;
    const float offset = (row % 2) ? 0.5f * kSpacing : 0.0f;
    for (int column = 0; column < 8; ++column) {
      const float x = offset + static_cast<float>(column) * kSpacing;
      const glm::vec2 p(x, y);
      const glm::vec2 mirror(-x, y);
      if (!inside_polygon(p, outline) || distance_to_polygon_edge(p, outline) < kOutlineMargin) continue;
      if (distance_to_points(p, points) < kMinDistance) continue;
      if (x > 0 && glm::length(p - mirror) < kMinDistance) continue;
      points.push_back(p);
      if (x > 0) points.push_back(mirror);
    }
  }
}

}  // namespace

bool inside_polygon(glm::vec2 p, const std::vector<glm::vec2>& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::vec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) inside = !inside;
  }
  return inside;
}

std::vector<glm::vec2> polygon_of(const FacePoints& face, const std::vector<std::uint32_t>& indices) {
  std::vector<glm::vec2> polygon;
  for (std::uint32_t i : indices) polygon.push_back(face.points[i]);
  return polygon;
}

std::vector<glm::vec2> landmark_polygon(int begin, int end) {
  const auto t = model::landmark_template();
  return {t.begin() + begin, t.begin() + end};
}

FacePoints place_face_points() {
  FacePoints face;
  auto& points = face.points;
  const auto tmpl = model::landmark_template();
  points.assign(tmpl.begin(), tmpl.end());

  // Outline: jaw (0..16, already CCW from the right ear under the chin to the
  // left ear), the left temple, the hairline arc, the right temple.
  for (int i = lm::kJawBegin; i < lm::kJawEnd; ++i) face.outline.push_back(static_cast<std::uint32_t>(i));
  const auto add_outline = [&](glm::vec2 p) {
    face.outline.push_back(static_cast<std::uint32_t>(points.size()));
    points.push_back(p);
  };
  add_outline({1.15f, 0.16f});
  for (const glm::vec2& p : hairline_arc()) add_outline(p);
  add_outline({-1.15f, 0.16f});

  add_eye_rings(lm::kEyeRightBegin, lm::kEyeRightEnd, points);
  add_eye_rings(lm::kEyeLeftBegin, lm::kEyeLeftEnd, points);
  for (int i = lm::kBrowRightBegin; i < lm::kBrowLeftEnd; ++i)  // a row above each brow
    points.push_back(tmpl[static_cast<std::size_t>(i)] + glm::vec2(0.0f, 0.14f));

  // A ring around the lips, so the mouth corners and the philtrum have vertices.
  const glm::vec2 mouth = mean_of(lm::kOuterLipBegin, lm::kOuterLipEnd);
  for (int i = lm::kOuterLipBegin; i < lm::kOuterLipEnd; ++i) {
    const glm::vec2 p = tmpl[static_cast<std::size_t>(i)];
    points.push_back(p + 0.13f * glm::normalize(p - mouth));
  }
  // Nose sides and wings.
  for (const float sign : {-1.0f, 1.0f}) {
    points.emplace_back(sign * 0.13f, -0.2f);
    points.emplace_back(sign * 0.17f, -0.42f);
    points.emplace_back(sign * 0.31f, -0.56f);
  }

  add_fill(polygon_of(face, face.outline), points);

  // Rim: the outline pushed outward, where the surface turns back toward the
  // ears and over the top of the head.
  face.first_rim_point = points.size();
  const glm::vec2 head_centre(0.0f, -0.3f);
  for (std::uint32_t i : face.outline) {
    face.rim.push_back(static_cast<std::uint32_t>(points.size()));
    points.push_back(points[i] + 0.24f * glm::normalize(points[i] - head_centre));
  }
  return face;
}

}  // namespace fw::facegen
