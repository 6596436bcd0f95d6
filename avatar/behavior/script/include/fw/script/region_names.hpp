#pragma once
// Region names as scripts write them, and what they stand for on facewire's
// faces: the regions of the generic face for AU definitions, the colour
// channels for vascular expressions. Names are compared ignoring case, so
// the paper's Capitalised_Names and facewire's snake_case both work.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fw::script {

/// The generic face's regions as avatar/model names them
/// (fw::model::kFaceRegionNames). This module may not include avatar/model,
/// so the list is repeated here and a test keeps the two equal.
inline constexpr std::array<std::string_view, 20> kFaceRegionNames = {
    "forehead", "hairline", "brow_right", "brow_left", "upper_lid_right", "upper_lid_left",
    "lower_lid_right", "lower_lid_left", "nose", "cheek_right", "cheek_left", "upper_lip",
    "lower_lip", "mouth_corner_right", "mouth_corner_left", "chin", "jaw_right", "jaw_left",
    "side_right", "side_left"};

/// The generic face's regions that a region name in an AU definition stands for:
/// - a region of the generic face: that region;
/// - a paired region without its side (brow, upper_lid, lower_lid, cheek,
///   mouth_corner, jaw, side): both sides;
/// - the paper's names: Above_Brow -> forehead, Brow -> both brows,
///   Below_Lower_Lid -> both cheeks (the generic face has no band between
///   the lower lid and the cheek); also brows, cheeks, lips.
/// @return empty if the name is none of these
std::vector<std::string> face_regions_for(std::string_view written);

/// The names face_regions_for() accepts, for messages.
std::string face_region_names_text();

/// The colour channels (script_meaning.hpp: FaceParams::blush regions, then
/// pallor) that a region of a vascular expression drives. The paper's
/// regions: forehead -> forehead; cheeks -> cheek_left and cheek_right;
/// nose -> nose; ears -> sides (the face texture ends in front of the ears,
/// so their flush shows on the sides of the face); head -> all five blush
/// regions. Also facewire's own channel names, cheek, ear, side, face (=
/// head), and pallor (FaceParams::pallor, the whole face paling).
/// @return channel indices; empty if the name is none of these
std::vector<std::size_t> colour_channels_for(std::string_view written);

/// "forehead", ..., "sides", "pallor".
std::string_view colour_channel_name(std::size_t channel);

/// The names colour_channels_for() accepts, for messages.
std::string colour_region_names_text();

}  // namespace fw::script
