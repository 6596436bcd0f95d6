#pragma once
// Distances to a polyline in image pixels, for lines drawn soft onto a
// texture (the lash lines of a closed lid, the line where closed lips meet).
#include <algorithm>
#include <vector>

#include <opencv2/core.hpp>

namespace fw::photo {

struct NearestOnPolyline {
  float distance = 1e9f;
  float along = 0;  ///< 0 at the polyline's first point .. 1 at its last
};

inline NearestOnPolyline nearest_on(const std::vector<cv::Point2f>& line, cv::Point2f p) {
  NearestOnPolyline best;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const cv::Point2f a = line[i], ab = line[i + 1] - line[i];
    const float t = std::clamp((p - a).dot(ab) / std::max(1e-6f, ab.dot(ab)), 0.0f, 1.0f);
    const float d = static_cast<float>(cv::norm(p - (a + t * ab)));
    if (d < best.distance) best = {d, (static_cast<float>(i) + t) / static_cast<float>(line.size() - 1)};
  }
  return best;
}

/// 1 within `half_width` of the line, fading to 0 over one more pixel.
inline float line_cover(float distance, float half_width) { return std::clamp(1.0f + half_width - distance, 0.0f, 1.0f); }

}  // namespace fw::photo
