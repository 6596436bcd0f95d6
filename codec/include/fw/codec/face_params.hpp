#pragma once
// FaceParams v2: everything a client needs to rebuild one face for one frame.
// Plain data: the bitstream (codec/FORMAT.md) quantises exactly these fields,
// and the web decoder mirrors them. Changing a field changes the schema id.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fw::codec {

/// Schema 2 added the corrective weights (the bitstream's format version 2).
inline constexpr std::uint16_t kFaceParamsSchema = 2;

/// The FACS action units a face can show.
inline constexpr std::array<std::uint8_t, 18> kActionUnits = {
    1, 2, 4, 5, 6, 7, 9, 10, 12, 14, 15, 17, 20, 23, 24, 25, 26, 27};
inline constexpr std::size_t kActionUnitCount = kActionUnits.size();

/// Which side of the face an action-unit channel moves. FACS scores the
/// paired muscles (brows, lids, cheeks, lip corners...) per side, so those
/// AUs have a left and a right channel; midline AUs (nose wrinkler, chin
/// raiser, lips apart, jaw drop, mouth stretch, lip tightener and pressor)
/// have one.
enum class AuSide : std::uint8_t { both, left, right };

struct AuChannel {
  std::uint8_t au;  ///< FACS number
  AuSide side;
};

/// FACS action units scored per side.
constexpr bool is_bilateral(int au) {
  switch (au) {
    case 1: case 2: case 4: case 5: case 6: case 7: case 10: case 12: case 14: case 15: case 20: return true;
    default: return false;
  }
}

/// The action-unit channels in FaceParams::au order: each AU in kActionUnits
/// order, bilateral ones as left then right.
inline constexpr std::size_t kAuChannelCount = [] {
  std::size_t n = 0;
  for (auto au : kActionUnits) n += is_bilateral(au) ? 2 : 1;
  return n;
}();
inline constexpr std::array<AuChannel, kAuChannelCount> kAuChannels = [] {
  std::array<AuChannel, kAuChannelCount> channels{};
  std::size_t i = 0;
  for (auto au : kActionUnits) {
    if (is_bilateral(au)) {
      channels[i++] = {au, AuSide::left};
      channels[i++] = {au, AuSide::right};
    } else {
      channels[i++] = {au, AuSide::both};
    }
  }
  return channels;
}();

/// Index of the channel of `au` on `side` (AuSide::both for midline AUs), or
/// -1 if FaceParams does not carry it.
constexpr int au_channel(int au, AuSide side) {
  for (std::size_t i = 0; i < kAuChannelCount; ++i)
    if (kAuChannels[i].au == au && kAuChannels[i].side == side) return static_cast<int>(i);
  return -1;
}

/// Skin regions whose blood flow the vascular channels control.
enum class ColourRegion : std::uint8_t { forehead, cheek_left, cheek_right, nose, sides, count };
inline constexpr std::size_t kColourRegionCount = static_cast<std::size_t>(ColourRegion::count);
inline constexpr std::array<std::string_view, kColourRegionCount> kColourRegionNames = {
    "forehead", "cheek_left", "cheek_right", "nose", "sides"};

/// Corrective components of the physics face (avatar/physics, the face
/// asset's `correctives`): what the simulated skin does beyond the sum of
/// its action units (the tissue's non-linear response to combined units and
/// to motion), as the weights of a few principal components of that
/// residual. Clients that draw the AU morphs alone may ignore them.
inline constexpr std::size_t kCorrectiveCount = 6;

/// One eye's rotation. Left and right are the person's own (the left eye is
/// on the viewer's right), so vergence is the difference of the two yaws.
struct EyeRotation {
  float yaw_rad = 0;    ///< [-0.6, 0.6], positive turns toward the person's left
  float pitch_rad = 0;  ///< [-0.5, 0.5], positive looks up
};

struct FaceParams {
  /// Action-unit intensities in [0,1] (0 absent, 1 the FACS maximum "E"),
  /// in kAuChannels order.
  std::array<float, kAuChannelCount> au{};
  /// Head rotation, applied roll, then pitch, then yaw, about the neck pivot.
  float head_yaw_rad = 0;    ///< [-1.2, 1.2], positive turns toward the person's left
  float head_pitch_rad = 0;  ///< [-0.8, 0.8], positive looks up
  float head_roll_rad = 0;   ///< [-0.6, 0.6], positive tilts toward the person's left shoulder
  /// Small head translation from the rest position in millimetres: x toward
  /// the person's left, y up, z toward the viewer; each in [-100, 100].
  std::array<float, 3> head_translation_mm{};
  EyeRotation eye_left;
  EyeRotation eye_right;
  /// Lid closure in [0,1]: 0 = the photo's open lid, 1 = fully closed.
  float lid_left = 0;
  float lid_right = 0;
  /// Blush intensity per region in [0,1] (raises redness and saturation).
  std::array<float, kColourRegionCount> blush{};
  /// Whole-face pallor in [0,1] (lowers saturation, shifts toward a paler tone).
  float pallor = 0;
  /// Corrective weights in [-1,1], one per component of the face asset's
  /// corrective basis (kCorrectiveCount): 0 on a face without physics.
  std::array<float, kCorrectiveCount> corrective{};

  /// Sets `au` to `intensity` on every side it has (both sides of a bilateral AU).
  void set_au(int au_number, float intensity);
  /// The intensity of `au` on `side`; for a bilateral AU asked with
  /// AuSide::both, the mean of its sides. 0 for an AU not carried.
  float au_intensity(int au_number, AuSide side = AuSide::both) const;
};

}  // namespace fw::codec
