#include "lash_line.hpp"

#include <algorithm>
#include <cmath>

#include "polyline_distance.hpp"

namespace fw::photo {
namespace {

void darken(cv::Vec3b& px, float amount, float to) {
  for (int c = 0; c < 3; ++c) px[c] = cv::saturate_cast<std::uint8_t>(px[c] * (1.0f - amount * (1.0f - to)));
}

}  // namespace

void draw_lash_lines(cv::Mat& lid, const std::array<std::vector<cv::Point2f>, 2>& eyes, float px_per_unit) {
  // Sizes at 64 px per unit (a 256 px face texture), scaled with the texture.
  const float scale = px_per_unit / 64.0f;
  const float lash_half_width = 0.5f * scale, outer_extra = 0.6f * scale;
  const float crease_rise = 0.07f * px_per_unit, crease_spread = 1.5f * scale;
  for (std::size_t side = 0; side < 2; ++side) {
    const std::vector<cv::Point2f>& eye = eyes[side];
    // Upper margin from the outer corner to the inner one; lower margin the
    // same way round. The person's right eye (36-41) starts at its outer
    // corner, the left eye (42-47) at its inner one.
    std::vector<cv::Point2f> upper(eye.begin(), eye.begin() + 4);
    std::vector<cv::Point2f> lower = {eye[0], eye[5], eye[4], eye[3]};
    if (side == 1) {
      std::reverse(upper.begin(), upper.end());
      std::reverse(lower.begin(), lower.end());
    }
    std::vector<cv::Point2f> crease;
    for (const cv::Point2f& p : upper) crease.emplace_back(p.x, p.y - crease_rise);
    // The eye with a few pixels around it, and the crease above.
    cv::Rect reach = cv::boundingRect(eye);
    const int margin = 4, above = static_cast<int>(crease_rise + 3 * crease_spread) + margin;
    reach.x -= margin;
    reach.width += 2 * margin;
    reach.y -= above;
    reach.height += above + margin;
    const cv::Rect area = reach & cv::Rect(0, 0, lid.cols, lid.rows);
    for (int y = area.y; y < area.y + area.height; ++y)
      for (int x = area.x; x < area.x + area.width; ++x) {
        const cv::Point2f p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        cv::Vec3b& px = lid.at<cv::Vec3b>(y, x);
        const NearestOnPolyline top = nearest_on(upper, p), bottom = nearest_on(lower, p), fold = nearest_on(crease, p);
        // The crease: a faint shadow, strongest over the middle of the lid.
        const float middle = std::clamp(1.0f - std::abs(fold.along - 0.5f) / 0.45f, 0.0f, 1.0f);
        darken(px, 0.14f * middle * std::exp(-(fold.distance * fold.distance) / (crease_spread * crease_spread)), 0.0f);
        // The lower margin: lashes there are fewer and paler.
        darken(px, 0.45f * line_cover(bottom.distance, 0.6f * lash_half_width), 0.4f);
        // The upper margin: thickest at the outer corner, where lashes are longest.
        const float outer = std::clamp((0.5f - top.along) / 0.5f, 0.0f, 1.0f);
        darken(px, 0.9f * line_cover(top.distance, lash_half_width + outer_extra * outer), 0.22f);
      }
  }
}

}  // namespace fw::photo
