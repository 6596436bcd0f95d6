#pragma once
// Display names as people see them: normalised to NFC, so that one name has
// one spelling, and refused when they hold characters that change how the
// text around them shows without showing themselves (controls, bidi
// overrides, zero-width characters): "\u202Eevil" would show reversed
// beside everyone's chat, and "Ada\u200B" would pass for Ada.
#include <string>
#include <string_view>

namespace fw::server {

/// `name` in NFC in `normalized`, and an empty result; else why it cannot
/// be a display name, for the person who chose it.
std::string normalize_display_name(std::string_view name, std::string& normalized);

}  // namespace fw::server
