#pragma once
// FaceParams v1: everything a client needs to rebuild one face for one frame.
// Plain data: the bitstream (codec/FORMAT.md) quantises exactly these fields,
// and the web decoder mirrors them. Changing a field changes the schema id.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fw::codec {

inline constexpr std::uint16_t kFaceParamsSchema = 1;

/// The FACS action units a face can show, in channel order. Intensities are in
/// [0,1] (0 = absent, 1 = the FACS "E" maximum).
inline constexpr std::array<std::uint8_t, 18> kActionUnits = {
    1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 24, 25, 26, 27};
inline constexpr std::size_t kActionUnitCount = kActionUnits.size();

/// Index of FACS action unit `au` in FaceParams::au, or -1 if it is not carried.
constexpr int action_unit_index(int au) {
  for (std::size_t i = 0; i < kActionUnitCount; ++i)
    if (kActionUnits[i] == au) return static_cast<int>(i);
  return -1;
}

/// Skin regions whose blood flow the vascular channels control.
enum class ColourRegion : std::uint8_t { forehead, cheek_left, cheek_right, nose, sides, count };
inline constexpr std::size_t kColourRegionCount = static_cast<std::size_t>(ColourRegion::count);
inline constexpr std::array<std::string_view, kColourRegionCount> kColourRegionNames = {
    "forehead", "cheek_left", "cheek_right", "nose", "sides"};

/// One eye's rotation. Left and right are the person's own (the left eye is
/// on the viewer's right), so vergence is the difference of the two yaws.
struct EyeRotation {
  float yaw_rad = 0;    ///< [-0.6, 0.6], positive turns toward the person's left
  float pitch_rad = 0;  ///< [-0.5, 0.5], positive looks up
};

struct FaceParams {
  /// Action-unit intensities in [0,1], in kActionUnits order.
  std::array<float, kActionUnitCount> au{};
  /// Head rotation, applied roll, then pitch, then yaw, about the neck pivot.
  float head_yaw_rad = 0;    ///< [-1.2, 1.2], positive turns toward the person's left
  float head_pitch_rad = 0;  ///< [-0.8, 0.8], positive looks up
  float head_roll_rad = 0;   ///< [-0.6, 0.6], positive tilts toward the person's left shoulder
  /// Small head translation in metres from the rest position: x toward the
  /// person's left, y up, z toward the viewer; each in [-0.1, 0.1].
  std::array<float, 3> head_translation_m{};
  EyeRotation eye_left;
  EyeRotation eye_right;
  /// Lid closure in [0,1]: 0 = the photo's open lid, 1 = fully closed.
  float lid_left = 0;
  float lid_right = 0;
  /// Blush intensity per region in [0,1] (raises redness and saturation).
  std::array<float, kColourRegionCount> blush{};
  /// Whole-face pallor in [0,1] (lowers saturation, shifts toward a paler tone).
  float pallor = 0;
};

}  // namespace fw::codec
