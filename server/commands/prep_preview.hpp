#pragma once
// The preview sheet of a prepared avatar, for a person to check the fit: the
// aligned photo texture with its landmarks, the avatar rendered neutral with
// the fitted landmarks over it, the avatar turned; below them the contact
// sheet (every expression, gaze left, right and up, a blink, blush, pallor).
#include <string>

#include "fw/photo/prepare_avatar.hpp"
#include "fw/model/image.hpp"

namespace fw::server {

/// nullopt-like failure: returns false and `error` if rendering fails.
bool make_prep_preview(const photo::PreparedAvatar& avatar, model::RgbaImage& sheet, std::string& error);

}  // namespace fw::server
