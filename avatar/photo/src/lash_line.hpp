#pragma once
// What makes a closed eye read as closed rather than as blank skin: the dark
// line of the lashes where the lids meet and a faint shadow in the crease.
#include <array>
#include <vector>

#include <opencv2/core.hpp>

namespace fw::photo {

/// Draws onto `lid` (BGR skin over the eyes) a soft dark lash line along
/// each upper lid margin (a pixel or two wide at 64 px per model unit,
/// wider toward the outer corner), a fainter one along the lower margin and
/// a faint crease shadow above the upper lid. `eyes`: the eye contours
/// (landmarks 36-41 and 42-47) in `lid`'s pixels; `px_per_unit`: its scale.
/// A closing lid brings its upper margin down onto the lower one, so the two
/// lines meet in one where the lids meet.
void draw_lash_lines(cv::Mat& lid, const std::array<std::vector<cv::Point2f>, 2>& eyes, float px_per_unit);

}  // namespace fw::photo
