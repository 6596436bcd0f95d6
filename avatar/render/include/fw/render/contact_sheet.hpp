#pragma once
// A contact sheet of one avatar: neutral, every expression, gaze directions,
// a blink, blushing and pallor, the head turned 30 and 60 degrees, in a
// fixed order (sheet_panels()). Used by `facewire-client render --sheet` and the prep preview.
#include <string>
#include <vector>

#include "fw/codec/face_params.hpp"
#include "fw/model/image.hpp"
#include "fw/render/avatar_appearance.hpp"

namespace fw::render {

struct SheetPanel {
  std::string name;
  codec::FaceParams params;
};

/// The panels, in order: neutral, joy, sadness, anger, fear, surprise,
/// disgust, cunning, teasing, gaze left, gaze right, gaze up, blink,
/// blush, pallor, turned 30, turned 60 (degrees, toward the face's left).
std::vector<SheetPanel> sheet_panels();

/// The columns that lay the panels out in whole rows.
inline constexpr int kSheetColumns = 6;

/// Renders the panels `columns` to a row, each `panel_size` square.
/// @return false and `error` if the renderer cannot be created
bool render_contact_sheet(const AvatarAppearance& appearance, int panel_size, int columns, model::RgbaImage& sheet,
                          std::string& error);

}  // namespace fw::render
